#include "view/present_pass.h"

namespace shadelab {

void recordBlitToSwapchain(VkCommandBuffer cmd, const Image& source, ImageUse& sourceUse,
                           VkImage swapchainImage, VkExtent2D extent) {
  imageBarrier(cmd, source.get(), VK_IMAGE_ASPECT_COLOR_BIT, sourceUse, ImageUse::TransferSource);
  sourceUse = ImageUse::TransferSource;
  imageBarrier(cmd, swapchainImage, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Acquired,
               ImageUse::TransferDest);
  VkImageBlit region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstSubresource = region.srcSubresource;
  region.srcOffsets[1] = {int32_t(extent.width), int32_t(extent.height), 1};
  region.dstOffsets[1] = region.srcOffsets[1];
  // Same size, nearest: a format conversion only (half float -> 8-bit sRGB).
  vkCmdBlitImage(cmd, source.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, swapchainImage,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
  imageBarrier(cmd, swapchainImage, VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::TransferDest,
               ImageUse::ColorAttachment);
}

void recordPresentTransition(VkCommandBuffer cmd, VkImage swapchainImage, VkExtent2D extent,
                             const Buffer* screenshot) {
  ImageUse use = ImageUse::ColorAttachment;
  if (screenshot) {
    imageBarrier(cmd, swapchainImage, VK_IMAGE_ASPECT_COLOR_BIT, use, ImageUse::TransferSource);
    use = ImageUse::TransferSource;
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, swapchainImage, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           screenshot->get(), 1, &region);
    transferToHostBarrier(cmd);
  }
  imageBarrier(cmd, swapchainImage, VK_IMAGE_ASPECT_COLOR_BIT, use, ImageUse::Present);
}

}  // namespace shadelab
