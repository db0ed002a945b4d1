#pragma once
// Mip generation pass: fills levels 1..n-1 of a texture from level 0 on the
// device, each level a linear-filter blit of the one above (for sRGB formats
// the blit filters in linear space, so averages are light, not code values).
// Every array layer is filtered on its own: a cube map's faces each from
// their own texels, so both sides of a face edge stay samples of one
// continuous image and the sampler's seamless cube filtering joins them.
// Reads: level 0, in TransferDest layout (just copied in).
// Writes: every level, left in ShaderRead layout.
#include "core/vulkan/context.h"

namespace shadelab {

class MipGeneration {
 public:
  // Throws VulkanError unless the device can blit and linearly filter the
  // texture formats (R8G8B8A8 _SRGB and _UNORM).
  explicit MipGeneration(const Context& context);
  void record(VkCommandBuffer cmd, VkImage image, uint32_t width, uint32_t height, uint32_t levels,
              uint32_t layers = 1) const;
};

}  // namespace shadelab
