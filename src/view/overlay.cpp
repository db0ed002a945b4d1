#include "view/overlay.h"

#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/image.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {
namespace {

void checkImguiVulkan(VkResult result) {
  VK_CHECK(result);
}

bool isSrgb(VkFormat format) {
  return format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_R8G8B8A8_SRGB;
}

// ImGui's colours are sRGB-encoded values; an _SRGB attachment encodes what
// the shader writes, so without decoding them first they come out washed out.
ImVec4 decoded(ImVec4 colour) {
  return {srgbToLinear(colour.x), srgbToLinear(colour.y), srgbToLinear(colour.z), colour.w};
}

VkRenderPass createLoadRenderPass(VkDevice device, VkFormat format) {
  VkAttachmentDescription attachment{};
  attachment.format = format;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the scene is already there
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachment.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference reference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  // Before and after: the barriers of present_pass (attachment use on both sides).
  VkSubpassDependency dependencies[2] = {};
  dependencies[0] = {VK_SUBPASS_EXTERNAL,
                     0,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                     0};
  dependencies[1] = {0,
                     VK_SUBPASS_EXTERNAL,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                     VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                     0};
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = dependencies;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &renderPass));
  return renderPass;
}

}  // namespace

Overlay::Overlay(const Context& context, VkFormat swapchainFormat, uint32_t minImageCount,
                 uint32_t imageCount)
    : context_(context) {
  VkDevice device = context.device();
  renderPass_ = createLoadRenderPass(device, swapchainFormat);
  // The backend allocates one set, for its font texture.
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  poolInfo.maxSets = 4;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &pool));
  descriptorPool_ = DescriptorPool(device, pool);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini written into the user's folder
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  srgbTarget_ = isSrgb(swapchainFormat);
  if (srgbTarget_)
    for (ImVec4& colour : ImGui::GetStyle().Colors) colour = decoded(colour);

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context.instance();
  info.PhysicalDevice = context.physicalDevice();
  info.Device = device;
  info.QueueFamily = context.queueFamily();
  info.Queue = context.queue();
  info.DescriptorPool = pool;
  info.MinImageCount = minImageCount;
  info.ImageCount = std::max(imageCount, minImageCount);
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkImguiVulkan;
  ImGui_ImplVulkan_Init(&info, renderPass_);
  context.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Overlay::~Overlay() {
  context_.waitIdle();
  ImGui_ImplVulkan_Shutdown();
  ImGui::DestroyContext();
  destroyFramebuffers();
  vkDestroyRenderPass(context_.device(), renderPass_, nullptr);
}

void Overlay::destroyFramebuffers() {
  for (VkFramebuffer framebuffer : framebuffers_)
    vkDestroyFramebuffer(context_.device(), framebuffer, nullptr);
  framebuffers_.clear();
}

void Overlay::setTargets(const std::vector<VkImageView>& views, VkExtent2D extent,
                         uint32_t minImageCount) {
  destroyFramebuffers();
  extent_ = extent;
  ImGui_ImplVulkan_SetMinImageCount(minImageCount);
  for (VkImageView view : views) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(context_.device(), &info, nullptr, &framebuffer));
    framebuffers_.push_back(framebuffer);
  }
}

// The help panel fills the window's width and takes as many columns (up to
// four) as its lines need to fit its height, each line wrapped to its
// column (or, where no count fits, the count whose table is least tall);
// lines are laid out down the first column, then the next. Leaves the panel
// open for the caller to add to and end.
void Overlay::drawHelp(const std::vector<std::string>& lines, int flags, float below) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  // Rows without vertical padding: at 640x360 the keys then fit in two columns.
  const ImVec2 cellPadding(style.CellPadding.x, 0.0f);
  const float width = std::max(float(extent_.width) - 16.0f, 64.0f);
  const float height =
      std::max(float(extent_.height) - 16.0f - 2.0f * style.WindowPadding.y - below, 16.0f);
  // The table's height: each row as tall as its most wrapped cell (the text
  // wrapped at the cell's width as TextWrapped wraps it), plus a line to spare.
  auto tableHeight = [&](int columns, size_t rows) {
    float cellWidth = std::max(
        (width - 2.0f * style.WindowPadding.x) / float(columns) - 2.0f * cellPadding.x, 1.0f);
    std::vector<float> rowHeights(rows, 0.0f);
    for (size_t i = 0; i < lines.size(); ++i)
      rowHeights[i % rows] = std::max(
          rowHeights[i % rows], ImGui::CalcTextSize(lines[i].c_str(), nullptr, false, cellWidth).y);
    float total = ImGui::GetTextLineHeightWithSpacing();
    for (float height : rowHeights) total += height;
    return total;
  };
  auto rowsFor = [&](int columns) {
    return (lines.size() + size_t(columns) - 1) / size_t(columns);
  };
  int columns = 1;
  float least = std::numeric_limits<float>::infinity();
  for (int count = 1; count <= 4; ++count) {
    float tall = tableHeight(count, rowsFor(count));
    if (tall <= height) {
      columns = count;
      break;
    }
    if (tall < least) {
      least = tall;
      columns = count;
    }
  }
  const size_t rows = rowsFor(columns);
  float panelWidth = width;
  if (columns == 1) {  // one column: as wide as its longest line
    float longest = 0.0f;
    for (const std::string& line : lines)
      longest = std::max(longest, ImGui::CalcTextSize(line.c_str()).x);
    panelWidth = std::min(width, longest + 2.0f * (style.WindowPadding.x + cellPadding.x) + 1.0f);
  }
  ImGui::SetNextWindowPos(ImVec2(8, 8));
  ImGui::SetNextWindowSize(ImVec2(panelWidth, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::Begin("help", nullptr, flags & ~ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, cellPadding);
  if (ImGui::BeginTable("keys", columns, ImGuiTableFlags_SizingStretchSame)) {
    for (size_t row = 0; row < rows; ++row) {
      ImGui::TableNextRow();
      for (int column = 0; column < columns; ++column) {
        ImGui::TableNextColumn();
        size_t i = size_t(column) * rows + row;
        if (i < lines.size()) ImGui::TextWrapped("%s", lines[i].c_str());
      }
    }
    ImGui::EndTable();
  }
  ImGui::PopStyleVar();
}

void Overlay::record(VkCommandBuffer cmd, uint32_t imageIndex, const OverlayText& text,
                     float deltaSeconds) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(float(extent_.width), float(extent_.height));
  io.DeltaTime = deltaSeconds > 0.0f ? deltaSeconds : 1.0f / 60.0f;
  ImGui_ImplVulkan_NewFrame();
  ImGui::NewFrame();
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoInputs |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  const float messageWrap = float(extent_.width) * 0.9f;
  auto drawMessage = [&] {
    if (text.message.empty()) return;
    ImVec4 colour =
        text.messageIsError ? ImVec4(1.0f, 0.25f, 0.2f, 1.0f) : ImVec4(1.0f, 0.85f, 0.3f, 1.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, srgbTarget_ ? decoded(colour) : colour);
    ImGui::PushTextWrapPos(messageWrap);
    ImGui::TextUnformatted(text.message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
  };
  if (text.help.empty()) {
    ImGui::SetNextWindowPos(ImVec2(8, 8));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("status", nullptr, flags);
    for (const std::string& line : text.status) ImGui::TextUnformatted(line.c_str());
    drawMessage();
    ImGui::End();
  } else {
    // In the status panel's place, so the two never overlap; the message
    // goes under the keys (PushTextWrapPos is window-local: the text wraps
    // messageWrap less the window's padding from its left edge).
    float below = 0.0f;
    if (!text.message.empty())
      below = ImGui::CalcTextSize(text.message.c_str(), nullptr, false,
                                  messageWrap - ImGui::GetStyle().WindowPadding.x)
                  .y +
              ImGui::GetStyle().ItemSpacing.y;
    drawHelp(text.help, flags, below);
    drawMessage();
    ImGui::End();
  }
  for (size_t i = 0; i < text.columnLabels.size(); ++i) {
    const OverlayText::Label& label = text.columnLabels[i];
    ImGui::SetNextWindowPos(ImVec2(label.left + 8, float(extent_.height) - 8), ImGuiCond_Always,
                            ImVec2(0, 1));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin(("column " + std::to_string(i)).c_str(), nullptr, flags);
    ImGui::TextUnformatted(label.text.c_str());
    ImGui::End();
  }
  ImGui::Render();

  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffers_[imageIndex];
  begin.renderArea = {{0, 0}, extent_};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
}

}  // namespace shadelab
