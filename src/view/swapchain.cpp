#include "view/swapchain.h"

#include <algorithm>

#include "core/base/errors.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {
namespace {

constexpr std::pair<const char*, VkPresentModeKHR> kPresentModes[] = {
    {"fifo", VK_PRESENT_MODE_FIFO_KHR},
    {"mailbox", VK_PRESENT_MODE_MAILBOX_KHR},
    {"immediate", VK_PRESENT_MODE_IMMEDIATE_KHR},
};

VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
  // An _SRGB format encodes on write, as writeImage does for PNG: the window
  // shows what `render` writes.
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB})
    for (const VkSurfaceFormatKHR& format : formats)
      if (format.format == wanted && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
        return format;
  throw VulkanError("the window surface offers no 8-bit sRGB format");
}

}  // namespace

VkPresentModeKHR parsePresentMode(const std::string& name) {
  for (const auto& [modeName, mode] : kPresentModes)
    if (name == modeName) return mode;
  throw InputError("--present '" + name + "': expected fifo, mailbox or immediate");
}

std::string presentModeName(VkPresentModeKHR mode) {
  for (const auto& [modeName, value] : kPresentModes)
    if (mode == value) return modeName;
  return "other";
}

Swapchain::Swapchain(const Context& context, VkSurfaceKHR surface, VkPresentModeKHR presentMode)
    : context_(context), surface_(surface), presentMode_(presentMode) {
  VkPhysicalDevice physical = context.physicalDevice();
  VkBool32 presentable = VK_FALSE;
  VK_CHECK(
      vkGetPhysicalDeviceSurfaceSupportKHR(physical, context.queueFamily(), surface, &presentable));
  if (!presentable) throw VulkanError("the graphics queue cannot present to this window");
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()));
  if (std::find(modes.begin(), modes.end(), presentMode) == modes.end()) {
    std::string offered;
    for (VkPresentModeKHR mode : modes)
      if (presentModeName(mode) != "other")
        offered += (offered.empty() ? "" : ", ") + presentModeName(mode);
    throw InputError("--present " + presentModeName(presentMode) +
                     ": this window system does not offer it (offered: " + offered + ")");
  }
  VkSurfaceFormatKHR format = chooseFormat(physical, surface);
  format_ = format.format;
  colorSpace_ = format.colorSpace;
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(physical, format_, &properties);
  if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
    throw VulkanError("the swapchain format cannot be a blit destination");
}

Swapchain::~Swapchain() {
  context_.waitIdle();
  destroyImages();
  if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
}

void Swapchain::destroyImages() {
  views_.clear();
  rawViews_.clear();
  renderingDone_.clear();
  images_.clear();
}

bool Swapchain::recreate(VkExtent2D wanted) {
  VkDevice device = context_.device();
  context_.waitIdle();  // the old images may still be drawn or presented
  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice(), surface_, &caps));
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == UINT32_MAX) {
    extent.width = std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height =
        std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  destroyImages();
  if (extent.width == 0 || extent.height == 0) {
    if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    extent_ = extent;
    return false;
  }
  // Transfer: the scene is blitted in and screenshots are copied out.
  VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                            VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if ((caps.supportedUsageFlags & usage) != usage)
    throw VulkanError("the swapchain images cannot be blitted to and copied from");
  minImageCount_ = std::max(2u, caps.minImageCount);
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount =
      caps.maxImageCount ? std::min(minImageCount_, caps.maxImageCount) : minImageCount_;
  info.imageFormat = format_;
  info.imageColorSpace = colorSpace_;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &created));
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = created;
  extent_ = extent;

  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format_;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
    views_.emplace_back(device, view);
    rawViews_.push_back(view);
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &semaphore));
    renderingDone_.emplace_back(device, semaphore);
  }
  return true;
}

SwapchainStatus Swapchain::acquire(VkSemaphore imageAvailable, uint32_t& imageIndex) {
  VkResult result = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, imageAvailable,
                                          VK_NULL_HANDLE, &imageIndex);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return SwapchainStatus::OutOfDate;
  if (result == VK_SUBOPTIMAL_KHR) return SwapchainStatus::Suboptimal;
  VK_CHECK(result);
  return SwapchainStatus::Ok;
}

SwapchainStatus Swapchain::present(uint32_t imageIndex) {
  VkSemaphore wait = renderingDone_[imageIndex];
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &imageIndex;
  VkResult result = vkQueuePresentKHR(context_.queue(), &info);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return SwapchainStatus::OutOfDate;
  if (result == VK_SUBOPTIMAL_KHR) return SwapchainStatus::Suboptimal;
  VK_CHECK(result);
  return SwapchainStatus::Ok;
}

}  // namespace shadelab
