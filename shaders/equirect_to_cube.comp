#version 460
// Equirectangular panorama -> cube map level 0: each cube texel samples the
// panorama along its own directions (bilinear, u wrapping, at the mip level
// whose texels match a cube texel), so every face edge is continuous.
#extension GL_GOOGLE_include_directive : require
#include "cube.glsl"
#include "interface.h"

layout(local_size_x = CUBE_BUILD_GROUP_SIZE, local_size_y = CUBE_BUILD_GROUP_SIZE) in;
layout(set = 0, binding = BINDING_CUBE_TARGET, rgba16f) uniform writeonly image2DArray target;
layout(set = 0, binding = BINDING_PANORAMA) uniform sampler2D panorama;
layout(push_constant) uniform PanoramaBlock { PanoramaParameters parameters; };

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  int size = parameters.face.x;
  if (texel.x >= size || texel.y >= size) return;
  // Turning the panorama by +a about y = looking it up along directions turned by -a.
  float c = cos(parameters.sampling.y), s = sin(parameters.sampling.y);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < CUBE_SUBSAMPLES; ++j)
    for (int i = 0; i < CUBE_SUBSAMPLES; ++i) {
      vec3 d = cubeSubsampleDirection(texel, size, i, j);
      vec3 turned = vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
      sum += textureLod(panorama, equirectCoordinates(turned), parameters.sampling.x).rgb;
    }
  vec3 color = parameters.sampling.z * sum / float(CUBE_SUBSAMPLES * CUBE_SUBSAMPLES);
  imageStore(target, texel, vec4(color, 1.0));
}
