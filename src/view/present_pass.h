#pragma once
// Presentation step: copies the renderer's linear colour target into a
// swapchain image (the blit encodes sRGB, as writeImage does for PNG) and
// hands the image to the presentation engine, copying it to a host buffer
// first when a screenshot is wanted.
// Reads: the colour target. Writes: the swapchain image (then ColorAttachment
// for the overlay), and the screenshot buffer.
#include "core/vulkan/barriers.h"
#include "core/vulkan/resources.h"

namespace shadelab {

// The swapchain image is in ImageUse::Acquired before, ColorAttachment after;
// `sourceUse` is updated. Source and destination have the same size.
void recordBlitToSwapchain(VkCommandBuffer cmd, const Image& source, ImageUse& sourceUse,
                           VkImage swapchainImage, VkExtent2D extent);

// ColorAttachment -> Present, through a copy into `screenshot` (4 bytes per
// pixel in the swapchain's format, host-visible) when it is not null.
void recordPresentTransition(VkCommandBuffer cmd, VkImage swapchainImage, VkExtent2D extent,
                             const Buffer* screenshot);

}  // namespace shadelab
