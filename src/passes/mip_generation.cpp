#include "passes/mip_generation.h"

#include <cassert>
#include <string>

#include "core/base/errors.h"
#include "core/scene/texture.h"
#include "core/vulkan/barriers.h"

namespace shadelab {

MipGeneration::MipGeneration(const Context& context) {
  const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_BLIT_SRC_BIT |
                                      VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  for (VkFormat format : {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R8G8B8A8_UNORM}) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
    if ((properties.optimalTilingFeatures & needed) != needed)
      throw VulkanError("device cannot blit with linear filtering in texture format " +
                        std::to_string(int(format)) + " (mip generation)");
  }
}

void MipGeneration::record(VkCommandBuffer cmd, VkImage image, uint32_t width, uint32_t height,
                           uint32_t levels, uint32_t layers) const {
  assert(levels == mipLevelCount(width, height) || levels == 1);
  for (uint32_t level = 1; level < levels; ++level) {
    imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferDest,
                 ImageUse::TransferSource, level - 1, 1);
    glm::uvec2 source = mipLevelSize(width, height, level - 1);
    glm::uvec2 target = mipLevelSize(width, height, level);
    // The whole source level onto the whole target level. Halving an even
    // size, each bilinear tap lands between 4 texels: a box filter. For odd
    // sizes (37 -> 18) the taps weigh source texels unevenly, as every
    // blit-based chain does; sizes and level count stay right.
    VkImageBlit2 region{VK_STRUCTURE_TYPE_IMAGE_BLIT_2};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, layers};
    region.srcOffsets[1] = {int32_t(source.x), int32_t(source.y), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers};
    region.dstOffsets[1] = {int32_t(target.x), int32_t(target.y), 1};
    VkBlitImageInfo2 blit{VK_STRUCTURE_TYPE_BLIT_IMAGE_INFO_2};
    blit.srcImage = image;
    blit.srcImageLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    blit.dstImage = image;
    blit.dstImageLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    blit.regionCount = 1;
    blit.pRegions = &region;
    blit.filter = VK_FILTER_LINEAR;
    vkCmdBlitImage2(cmd, &blit);
  }
  if (levels > 1)
    imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferSource,
                 ImageUse::ShaderRead, 0, levels - 1);
  imageBarrier(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferDest, ImageUse::ShaderRead,
               levels - 1, 1);
}

}  // namespace shadelab
