#pragma once
// Image layout transitions from the before/after use of an image: the one
// place stages, access masks and layouts are chosen (synchronization2).
#include <vulkan/vulkan.h>

namespace shadelab {

enum class ImageUse {
  Undefined,        // contents may be discarded
  ColorAttachment,  // written by a render pass
  DepthAttachment,  // read and written by depth testing
  TransferSource,   // copied or blitted from
  TransferDest,     // copied or blitted to
  ShaderRead,       // sampled by fragment shaders
  ComputeWrite,     // written as a storage image by compute shaders
  ComputeRead,      // sampled by compute shaders
  Present,          // handed to the presentation engine
  Acquired,         // a swapchain image just acquired: contents discarded; the
                    // acquire semaphore is waited on at the transfer stage
};

void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, ImageUse before,
                  ImageUse after, uint32_t baseMip = 0,
                  uint32_t mipCount = VK_REMAINING_MIP_LEVELS);

// Makes transfer writes to host-visible memory available to the host.
void transferToHostBarrier(VkCommandBuffer cmd);

}  // namespace shadelab
