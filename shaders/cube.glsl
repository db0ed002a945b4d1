// Cube map and panorama addressing (mirrored in src/core/scene/environment.cpp).
// Faces are array layers 0..5 = +X, -X, +Y, -Y, +Z, -Z with (s, t) as in
// Vulkan's cube map face selection table; the panorama's centre looks along
// -Z, u = 0.75 along +X, v = 0 straight up.
#ifndef CUBE_GLSL
#define CUBE_GLSL

const float PI = 3.14159265358979;

// The direction through (s, t) on `face`: the face table, inverted.
vec3 cubeFaceDirection(int face, vec2 st) {
  vec2 c = 2.0 * st - 1.0;  // (sc, tc) / |ma|
  if (face == 0) return vec3(1.0, -c.y, -c.x);   // +X: sc = -rz, tc = -ry
  if (face == 1) return vec3(-1.0, -c.y, c.x);   // -X: sc = +rz, tc = -ry
  if (face == 2) return vec3(c.x, 1.0, c.y);     // +Y: sc = +rx, tc = +rz
  if (face == 3) return vec3(c.x, -1.0, -c.y);   // -Y: sc = +rx, tc = -rz
  if (face == 4) return vec3(c.x, -c.y, 1.0);    // +Z: sc = +rx, tc = -ry
  return vec3(-c.x, -c.y, -1.0);                 // -Z: sc = -rx, tc = -ry
}

vec2 equirectCoordinates(vec3 d) {
  float u = 0.5 + atan(d.x, -d.z) / (2.0 * PI);
  float v = acos(clamp(d.y / length(d), -1.0, 1.0)) / PI;
  return vec2(u, v);
}

// One cube texel is the mean of 2x2 directions inside it: antialiases the
// sun's edge and a panorama's detail a little beyond bilinear.
const int CUBE_SUBSAMPLES = 2;
vec3 cubeSubsampleDirection(ivec3 texel, int size, int i, int j) {
  vec2 st = (vec2(texel.xy) + (vec2(i, j) + 0.5) / float(CUBE_SUBSAMPLES)) / float(size);
  return normalize(cubeFaceDirection(texel.z, st));
}
#endif
