#version 460
// Billboard pass, vertex stage: one quad per instance, six vertices, no
// vertex buffer. The instance's anchor and up come in eye space
// (BillboardInstance, written per frame by the host); the quad's corners are
// built here, in eye space, so the quad is a real surface with real depth
// and meets the ground where it stands. Kinds (SPEC_BILLBOARD_KIND):
//   screen       right = x_eye, up = y_eye: parallel to the image plane;
//   spherical    normal towards the eye point, right = up x normal: faces the
//                viewer wherever it stands, tilting as the eye rises;
//   cylindrical  up = its axis, right = axis x (towards the eye): turns about
//                the axis only, so seen along the axis it is edge-on;
//   impostor     right and up as the host chose them: the axes of the atlas
//                cell captured nearest the view direction (core/scene/
//                impostor.h), so the quad lies where the captured image did.
//                Built with IMPOSTOR_BLEND (billboard_impostor_blend.vert,
//                --impostor-blend on): normal towards the eye point, up as
//                near the mesh's y axis as that allows (impostorFrame's axes
//                for the view); the fragment stage finds the three blended
//                cells' images on it, so this stage hands on their axes.
// optics.y: where the anchor sits on the quad's height (0 bottom, 0.5 centre);
// optics.w = 1: each copy is its outline triangle instead of the quad.
#extension GL_GOOGLE_include_directive : require
#include "impostor_atlas.glsl"
#include "lighting.glsl"

layout(constant_id = SPEC_BILLBOARD_KIND) const int kind = BILLBOARD_CYLINDRICAL;

layout(set = 2, binding = BINDING_BILLBOARD_INSTANCES, std430) readonly buffer InstanceBlock {
  BillboardInstance instances[];
};

layout(location = 0) out vec3 outPosition;  // eye space
layout(location = 1) flat out vec3 outNormal;    // eye space, unit
layout(location = 4) out vec2 outUv;
layout(location = 5) flat out vec4 outTangent;  // eye space: the quad's right, w = 1
#ifdef IMPOSTOR_BLEND
// Per blended cell, its image's axes in eye space; right.w = its weight,
// up.w = its index in the atlas. outTangent.w = the quad's half side.
layout(location = 6) flat out vec4 outCellRight[3];
layout(location = 9) flat out vec4 outCellUp[3];
layout(location = 12) flat out vec3 outImpostorCentre;  // eye space
#endif

// A unit vector perpendicular to `axis`, for a view along it (degenerate).
vec3 anyPerpendicular(vec3 axis) {
  vec3 r = cross(axis, vec3(0.0, 0.0, 1.0));
  if (dot(r, r) < 1e-12) r = cross(axis, vec3(1.0, 0.0, 0.0));
  return normalize(r);
}

#ifdef IMPOSTOR_BLEND
// v rotated by the unit quaternion q (xyz, w).
vec3 rotated(vec4 q, vec3 v) {
  return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

// impostor.cpp's octahedralDecode and impostorFrame, for a cell's centre:
// the direction it was captured from and its image's right and up, in the
// mesh's space.
void impostorCellAxes(int cell, int cells, out vec3 right, out vec3 up) {
  vec2 point = (vec2(float(cell % cells), float(cell / cells)) + 0.5) / float(cells) * 2.0 - 1.0;
  vec3 d = vec3(point.x, 1.0 - abs(point.x) - abs(point.y), point.y);
  if (d.y < 0.0)
    d.xz = vec2((1.0 - abs(d.z)) * (d.x < 0.0 ? -1.0 : 1.0),
                (1.0 - abs(d.x)) * (d.z < 0.0 ? -1.0 : 1.0));
  d = normalize(d);
  vec3 r = cross(vec3(0.0, 1.0, 0.0), d);
  right = dot(r, r) > 1e-12 ? normalize(r) : vec3(1.0, 0.0, 0.0);
  up = cross(d, right);
}
#endif

void main() {
  BillboardInstance instance = instances[gl_InstanceIndex];
  vec3 anchor = instance.centre.xyz;
  vec3 right, up, normal;
  if (kind == BILLBOARD_SCREEN) {
    right = vec3(1.0, 0.0, 0.0);
    up = vec3(0.0, 1.0, 0.0);
    normal = vec3(0.0, 0.0, 1.0);
  } else if (kind == BILLBOARD_SPHERICAL) {
    normal = safeNormalize(-anchor);
    if (dot(normal, normal) == 0.0) normal = vec3(0.0, 0.0, 1.0);  // the eye at the anchor
    vec3 r = cross(instance.up.xyz, normal);
    right = dot(r, r) > 1e-12 ? normalize(r) : anyPerpendicular(normal);
    up = cross(normal, right);
  } else if (kind == BILLBOARD_IMPOSTOR) {
#ifdef IMPOSTOR_BLEND
    normal = safeNormalize(-anchor);
    if (dot(normal, normal) == 0.0) normal = vec3(0.0, 0.0, 1.0);
    vec3 r = cross(rotated(instance.up, vec3(0.0, 1.0, 0.0)), normal);
    right = dot(r, r) > 1e-12 ? normalize(r) : rotated(instance.up, vec3(1.0, 0.0, 0.0));
    up = cross(normal, right);
#else
    right = instance.right.xyz;
    up = instance.up.xyz;
    normal = cross(right, up);
#endif
  } else {
    up = instance.up.xyz;
    vec3 r = cross(up, -anchor);
    right = dot(r, r) > 1e-12 ? normalize(r) : anyPerpendicular(up);
    normal = cross(right, up);
  }
  // Two counter-clockwise triangles: (0,0) (1,0) (1,1), (0,0) (1,1) (0,1), as
  // bits of two masks (vertex i's x is bit i of 0b010110, y of 0b110100):
  // llvmpipe turns an indexed constant array into a per-lane gather.
  vec2 corner = vec2(float((22 >> gl_VertexIndex) & 1), float((52 >> gl_VertexIndex) & 1));
  // A trimmed copy: three vertices, the corners of its outline triangle
  // (core/scene/billboard_outline.h), in the same quad coordinates.
  if (draw.optics.w > 0.5)
    corner = unpackHalf2x16(gl_VertexIndex == 0   ? instance.outline.x
                            : gl_VertexIndex == 1 ? instance.outline.y
                                                  : instance.outline.z);
  float height = instance.up.w;
#ifdef IMPOSTOR_BLEND
  height = instance.centre.w;  // square; up holds the rotation
#endif
  vec3 eye = anchor + right * ((corner.x - 0.5) * instance.centre.w) +
             up * ((corner.y - draw.optics.y) * height);
  outPosition = eye;
  outNormal = normal;
  outUv = corner;
#ifdef IMPOSTOR_BLEND
  if (kind == BILLBOARD_IMPOSTOR) {
    for (int k = 0; k < 3; ++k) {
      int cell = int(instance.right[k]);
      vec3 cellRight, cellUp;
      impostorCellAxes(cell, int(draw.optics.z), cellRight, cellUp);
      outCellRight[k] = vec4(rotated(instance.up, cellRight), uintBitsToFloat(instance.outline[k]));
      outCellUp[k] = vec4(rotated(instance.up, cellUp), float(cell));
    }
    outImpostorCentre = anchor;
  }
#else
  if (kind == BILLBOARD_IMPOSTOR) {
    outUv = impostorAtlasCoordinate(int(instance.right.w), int(draw.optics.z), corner);
  }
#endif
  // w: the handedness (+1), or for an impostor its half size in eye units,
  // which scales the heights its normal map's alpha holds (billboard.frag).
  outTangent = vec4(right, kind == BILLBOARD_IMPOSTOR ? 0.5 * instance.centre.w : 1.0);
  gl_Position = frame.projection * vec4(eye, 1.0);
}
