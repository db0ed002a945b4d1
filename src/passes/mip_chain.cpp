#include "passes/mip_chain.h"

#include <algorithm>

namespace shadelab {

void recordMipChain(VkCommandBuffer cmd, const Image& image, ImageUse level0Use,
                    ImageUse finalUse) {
  const ImageDesc& desc = image.desc();
  VkImage handle = image.get();
  imageBarrier(cmd, handle, VK_IMAGE_ASPECT_COLOR_BIT, level0Use, ImageUse::TransferSource, 0, 1);
  int32_t width = int32_t(desc.width), height = int32_t(desc.height);
  for (uint32_t level = 1; level < desc.mipLevels; ++level) {
    int32_t nextWidth = std::max(1, width / 2), nextHeight = std::max(1, height / 2);
    imageBarrier(cmd, handle, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::TransferDest, level, 1);
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, desc.layers};
    blit.srcOffsets[1] = {width, height, 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, desc.layers};
    blit.dstOffsets[1] = {nextWidth, nextHeight, 1};
    vkCmdBlitImage(cmd, handle, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, handle,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    imageBarrier(cmd, handle, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferDest,
                 ImageUse::TransferSource, level, 1);
    width = nextWidth, height = nextHeight;
  }
  imageBarrier(cmd, handle, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferSource, finalUse);
}

}  // namespace shadelab
