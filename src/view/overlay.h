#pragma once
// The viewer's text overlay: Dear ImGui drawn over the presented image in a
// classic render pass that loads what the scene left (ImGui 1.86's Vulkan
// backend knows no dynamic rendering).
#include <string>
#include <vector>

#include "core/vulkan/context.h"
#include "core/vulkan/resources.h"

namespace shadelab {

struct OverlayText {
  std::vector<std::string> status;  // top-left panel, one line each
  std::string message;              // the last action's result or error, if any
  bool messageIsError = false;
  std::vector<std::string> help;  // when not empty, shown instead of the status panel
  struct Label {
    float left = 0.0f;  // pixels from the window's left edge
    std::string text;
  };
  std::vector<Label> columnLabels;  // split screen: a name at the foot of each column
};

class Overlay {
 public:
  Overlay(const Context& context, VkFormat swapchainFormat, uint32_t minImageCount,
          uint32_t imageCount);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // After every swapchain (re)creation: one framebuffer per image view.
  void setTargets(const std::vector<VkImageView>& views, VkExtent2D extent, uint32_t minImageCount);
  // Lays out the text and records it onto swapchain image `imageIndex`, which
  // is in ImageUse::ColorAttachment and stays there.
  void record(VkCommandBuffer cmd, uint32_t imageIndex, const OverlayText& text,
              float deltaSeconds);

 private:
  const Context& context_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  DescriptorPool descriptorPool_;
  std::vector<VkFramebuffer> framebuffers_;
  VkExtent2D extent_{0, 0};
  bool srgbTarget_ = false;
  void destroyFramebuffers();
  // `below`: the height the caller adds to the panel after the lines (the
  // message line), kept free so that it stays inside the window.
  void drawHelp(const std::vector<std::string>& lines, int flags, float below) const;
};

}  // namespace shadelab
