#pragma once
// Owned Vulkan objects: small move-only types that destroy in their
// destructor, the one ownership scheme used throughout shadelab.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <utility>

namespace shadelab {

class Context;

// A device-level handle destroyed with vkDestroyX(device, handle, nullptr).
template <typename Handle, void (*Destroy)(VkDevice, Handle, const VkAllocationCallbacks*)>
class DeviceHandle {
 public:
  DeviceHandle() = default;
  DeviceHandle(VkDevice device, Handle handle) : device_(device), handle_(handle) {}
  ~DeviceHandle() { reset(); }
  DeviceHandle(DeviceHandle&& other) noexcept
      : device_(other.device_), handle_(std::exchange(other.handle_, Handle(VK_NULL_HANDLE))) {}
  DeviceHandle& operator=(DeviceHandle&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, Handle(VK_NULL_HANDLE));
    }
    return *this;
  }
  DeviceHandle(const DeviceHandle&) = delete;
  DeviceHandle& operator=(const DeviceHandle&) = delete;

  Handle get() const { return handle_; }
  operator Handle() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }
  void reset() {
    if (handle_ != VK_NULL_HANDLE) Destroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
};

using ShaderModule = DeviceHandle<VkShaderModule, vkDestroyShaderModule>;
using Pipeline = DeviceHandle<VkPipeline, vkDestroyPipeline>;
using PipelineLayout = DeviceHandle<VkPipelineLayout, vkDestroyPipelineLayout>;
using DescriptorSetLayout = DeviceHandle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using DescriptorPool = DeviceHandle<VkDescriptorPool, vkDestroyDescriptorPool>;
using Sampler = DeviceHandle<VkSampler, vkDestroySampler>;
using ImageView = DeviceHandle<VkImageView, vkDestroyImageView>;
using CommandPool = DeviceHandle<VkCommandPool, vkDestroyCommandPool>;
using Fence = DeviceHandle<VkFence, vkDestroyFence>;
using Semaphore = DeviceHandle<VkSemaphore, vkDestroySemaphore>;
using QueryPool = DeviceHandle<VkQueryPool, vkDestroyQueryPool>;
using BufferHandle = DeviceHandle<VkBuffer, vkDestroyBuffer>;
using ImageHandle = DeviceHandle<VkImage, vkDestroyImage>;

// A command pool on the context's queue family (`flags`: its create flags)
// and one primary command buffer from it, freed with the pool.
struct CommandBufferPool {
  CommandPool pool;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
};
CommandBufferPool createCommandBuffer(const Context& context, VkCommandPoolCreateFlags flags);
Fence createFence(VkDevice device);  // unsignalled

// Device memory that counts itself into deviceMemoryInUse() while it lives,
// so the benchmark can report what each setting allocates.
class DeviceMemory {
 public:
  DeviceMemory() = default;
  DeviceMemory(VkDevice device, VkDeviceMemory memory, VkDeviceSize size);
  ~DeviceMemory() { reset(); }
  DeviceMemory(DeviceMemory&& other) noexcept;
  DeviceMemory& operator=(DeviceMemory&& other) noexcept;
  VkDeviceMemory get() const { return handle_.get(); }
  operator VkDeviceMemory() const { return handle_.get(); }
  void reset();

 private:
  DeviceHandle<VkDeviceMemory, vkFreeMemory> handle_;
  VkDeviceSize size_ = 0;
};

// Bytes allocated now, by every DeviceMemory of the process.
uint64_t deviceMemoryInUse();

enum class MemoryUse {
  DeviceLocal,  // written by transfers, read by the device
  HostVisible,  // mapped persistently: per-frame uniforms, staging, readback
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse memory);
  VkBuffer get() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }
  // Non-null only for MemoryUse::HostVisible (host-coherent memory).
  void* mapped() const { return mapped_; }
  explicit operator bool() const { return bool(buffer_); }

 private:
  // Members destroy in reverse order: the buffer before its memory.
  DeviceMemory memory_;
  BufferHandle buffer_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

struct ImageDesc {
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t mipLevels = 1;
  uint32_t layers = 1;
  VkImageUsageFlags usage = 0;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  bool arrayView = false;  // view as a 2D array (else 6 layers make a cube, 1 a 2D image)
};

class Image {
 public:
  Image() = default;
  Image(const Context& context, const ImageDesc& desc);
  VkImage get() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }
  const ImageDesc& desc() const { return desc_; }
  explicit operator bool() const { return bool(image_); }

 private:
  DeviceMemory memory_;
  ImageHandle image_;
  ImageView view_;
  ImageDesc desc_;
};

// Creates a device-local buffer holding `bytes`, uploaded through a staging
// buffer with a one-shot submit (load time only).
Buffer uploadBuffer(const Context& context, std::span<const std::byte> bytes,
                    VkBufferUsageFlags usage);

}  // namespace shadelab
