// KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv with
// R = [[cos, sin], [-sin, cos]] (the extension's matrices), in the glTF uv
// space the textures are sampled in (origin at the image's top left). The
// extension's GLSL listing, read column-major, has the opposite sign; its
// worked example, Blender, Babylon.js and the sample model agree with this
// one (KhronosGroup/glTF issue #1563).
// offsetScale: xy = offset, zw = scale.
#ifndef UV_TRANSFORM_GLSL
#define UV_TRANSFORM_GLSL
vec2 transformedCoordinate(vec2 st, vec4 offsetScale, float rotation) {
  vec2 scaled = st * offsetScale.zw;
  float c = cos(rotation), s = sin(rotation);
  return vec2(c * scaled.x + s * scaled.y, c * scaled.y - s * scaled.x) + offsetScale.xy;
}
#endif
