#version 460
// Procedural sky -> cube map level 0, one invocation per texel of each face.
#extension GL_GOOGLE_include_directive : require
#include "cube.glsl"
#include "sky.glsl"

layout(local_size_x = CUBE_BUILD_GROUP_SIZE, local_size_y = CUBE_BUILD_GROUP_SIZE) in;
layout(set = 0, binding = BINDING_CUBE_TARGET, rgba16f) uniform writeonly image2DArray target;
layout(push_constant) uniform SkyBlock { SkyParameters sky; };

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = sky.face.x;
  if (texel.x >= size || texel.y >= size) return;
  vec3 sum = vec3(0.0);
  for (int j = 0; j < CUBE_SUBSAMPLES; ++j)
    for (int i = 0; i < CUBE_SUBSAMPLES; ++i)
      sum += skyRadiance(sky, cubeSubsampleDirection(texel, size, i, j));
  imageStore(target, texel, vec4(sum / float(CUBE_SUBSAMPLES * CUBE_SUBSAMPLES), 1.0));
}
