#pragma once
// Mip generation on the device: each level is a linear blit of the one
// above it (a 2x2 box filter for power-of-two sizes), every array layer at
// once. For a cube map each face is filtered on its own; texels beside a
// face edge average only that face, so both sides of an edge stay samples
// of one continuous image and the sampler's seamless cube filtering joins them.
// Reads: level 0 in `level0Use`. Writes: levels 1.., then leaves every level in `finalUse`.
#include <vulkan/vulkan.h>

#include "core/barriers.h"
#include "core/resources.h"

namespace shadelab {

void recordMipChain(VkCommandBuffer cmd, const Image& image, ImageUse level0Use,
                    ImageUse finalUse = ImageUse::ShaderRead);

}  // namespace shadelab
