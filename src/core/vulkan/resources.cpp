#include "core/vulkan/resources.h"

#include <atomic>
#include <cstring>

#include "core/vulkan/context.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {
namespace {

std::atomic<uint64_t> memoryInUse{0};

}  // namespace

DeviceMemory::DeviceMemory(VkDevice device, VkDeviceMemory memory, VkDeviceSize size)
    : handle_(device, memory), size_(size) {
  memoryInUse.fetch_add(size);
}

DeviceMemory::DeviceMemory(DeviceMemory&& other) noexcept
    : handle_(std::move(other.handle_)), size_(std::exchange(other.size_, 0)) {}

DeviceMemory& DeviceMemory::operator=(DeviceMemory&& other) noexcept {
  if (this != &other) {
    reset();
    handle_ = std::move(other.handle_);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

void DeviceMemory::reset() {
  if (handle_) memoryInUse.fetch_sub(size_);
  handle_.reset();
  size_ = 0;
}

uint64_t deviceMemoryInUse() {
  return memoryInUse.load();
}

Buffer::Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
               MemoryUse memory)
    : size_(size) {
  VkDevice device = context.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
  buffer_ = BufferHandle(device, buffer);

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  VkMemoryPropertyFlags flags =
      memory == MemoryUse::HostVisible
          ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
          : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex = context.findMemoryType(requirements.memoryTypeBits, flags);
  VkDeviceMemory deviceMemory = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &deviceMemory));
  memory_ = DeviceMemory(device, deviceMemory, alloc.allocationSize);
  VK_CHECK(vkBindBufferMemory(device, buffer, deviceMemory, 0));
  if (memory == MemoryUse::HostVisible) {
    VK_CHECK(vkMapMemory(device, deviceMemory, 0, VK_WHOLE_SIZE, 0, &mapped_));
    // Deterministic contents even where a caller reads before writing.
    std::memset(mapped_, 0, size_t(size));
  }
}

Image::Image(const Context& context, const ImageDesc& desc) : desc_(desc) {
  VkDevice device = context.device();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  bool cube = desc.layers == 6 && !desc.arrayView;
  info.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = desc.mipLevels;
  info.arrayLayers = desc.layers;
  info.samples = desc.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
  image_ = ImageHandle(device, image);

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device, image, &requirements);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex =
      context.findMemoryType(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory deviceMemory = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &deviceMemory));
  memory_ = DeviceMemory(device, deviceMemory, alloc.allocationSize);
  VK_CHECK(vkBindImageMemory(device, image, deviceMemory, 0));

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = cube             ? VK_IMAGE_VIEW_TYPE_CUBE
                      : desc.arrayView ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                       : VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = desc.format;
  viewInfo.subresourceRange = {desc.aspect, 0, desc.mipLevels, 0, desc.layers};
  VkImageView view = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
  view_ = ImageView(device, view);
}

Buffer uploadBuffer(const Context& context, std::span<const std::byte> bytes,
                    VkBufferUsageFlags usage) {
  VkDeviceSize size = bytes.empty() ? 16 : bytes.size();  // zero-sized buffers are invalid
  Buffer staging(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostVisible);
  if (!bytes.empty()) std::memcpy(staging.mapped(), bytes.data(), bytes.size());
  Buffer buffer(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::DeviceLocal);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(cmd, staging.get(), buffer.get(), 1, &region);
  });
  return buffer;
}

CommandBufferPool createCommandBuffer(const Context& context, VkCommandPoolCreateFlags flags) {
  VkDevice device = context.device();
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = flags;
  poolInfo.queueFamilyIndex = context.queueFamily();
  VkCommandPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
  CommandBufferPool result{CommandPool(device, pool)};
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = pool;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VK_CHECK(vkAllocateCommandBuffers(device, &allocInfo, &result.cmd));
  return result;
}

Fence createFence(VkDevice device) {
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
  return Fence(device, fence);
}

}  // namespace shadelab
