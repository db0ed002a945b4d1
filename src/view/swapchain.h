#pragma once
// The window's swapchain: images, views and one "rendering done" semaphore
// per image, recreated on resize and restore. Acquire and present report
// OUT_OF_DATE / SUBOPTIMAL as a result, not an error.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "core/vulkan/context.h"
#include "core/vulkan/resources.h"

namespace shadelab {

enum class SwapchainStatus { Ok, Suboptimal, OutOfDate };

// Owns a VkSurfaceKHR; destroyed before the instance.
class Surface {
 public:
  Surface(VkInstance instance, VkSurfaceKHR surface) : instance_(instance), surface_(surface) {}
  ~Surface() { vkDestroySurfaceKHR(instance_, surface_, nullptr); }
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;
  VkSurfaceKHR get() const { return surface_; }

 private:
  VkInstance instance_;
  VkSurfaceKHR surface_;
};

VkPresentModeKHR parsePresentMode(const std::string& name);  // fifo, mailbox, immediate
std::string presentModeName(VkPresentModeKHR mode);

class Swapchain {
 public:
  // Throws InputError when the surface does not offer `presentMode`.
  Swapchain(const Context& context, VkSurfaceKHR surface, VkPresentModeKHR presentMode);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // Waits for the device, then builds for the surface's current extent
  // (falling back to `wanted` when the surface leaves it to us). Returns false
  // when the extent is 0x0 (minimised): no swapchain until the next call.
  bool recreate(VkExtent2D wanted);
  bool valid() const { return swapchain_ != VK_NULL_HANDLE; }

  SwapchainStatus acquire(VkSemaphore imageAvailable, uint32_t& imageIndex);
  SwapchainStatus present(uint32_t imageIndex);

  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  uint32_t minImageCount() const { return minImageCount_; }
  uint32_t imageCount() const { return uint32_t(images_.size()); }
  VkImage image(uint32_t index) const { return images_[index]; }
  const std::vector<VkImageView>& views() const { return rawViews_; }
  VkSemaphore renderingDone(uint32_t index) const { return renderingDone_[index]; }
  VkPresentModeKHR presentMode() const { return presentMode_; }

 private:
  void destroyImages();
  const Context& context_;
  VkSurfaceKHR surface_;
  VkPresentModeKHR presentMode_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR colorSpace_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkExtent2D extent_{0, 0};
  uint32_t minImageCount_ = 2;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  std::vector<VkImage> images_;
  std::vector<ImageView> views_;
  std::vector<VkImageView> rawViews_;
  // Per image, not per frame: an image's present may still read its
  // semaphore when the frame slot comes round again.
  std::vector<Semaphore> renderingDone_;
};

}  // namespace shadelab
