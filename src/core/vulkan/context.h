#pragma once
// Instance, physical device, logical device and queue: the Vulkan 1.3 setup
// every other part of shadelab builds on. Knows nothing of windows; a viewer
// passes the instance and device extensions it needs.
#include <vulkan/vulkan.h>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace shadelab {

struct ContextOptions {
  bool validation = false;
  std::string deviceName;  // substring of the device name; empty = first Vulkan 1.3 device
  std::vector<const char*> instanceExtensions;
  std::vector<const char*> deviceExtensions;
  bool echoValidation = true;  // also print each validation message to stderr
  // glibc keeps freed blocks in the heap instead of unmapping them (mallopt,
  // process-wide, once): lavapipe's per-draw allocations otherwise make one
  // frame in four 3x slower. Off for a program that must keep glibc's defaults.
  bool keepFreedMemoryInHeap = true;
};

struct DeviceDescription {
  std::string name;
  std::string driverName;
  std::string driverInfo;
  uint32_t apiVersion = 0;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
};

// Counts what the validation layer reported; tests fail on any.
struct ValidationReport {
  uint32_t errors = 0;
  uint32_t warnings = 0;
  std::vector<std::string> messages;
  uint32_t total() const { return errors + warnings; }
};

class Context {
 public:
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceFeatures& features() const { return features_; }
  DeviceDescription description() const;
  bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }

  ValidationReport validationReport() const;
  void resetValidationReport();

  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;
  // Records commands into a one-shot command buffer, submits and waits: for
  // load-time uploads and readbacks only, never in the frame loop.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;
  void waitIdle() const;

  static std::vector<DeviceDescription> listDevices();

 private:
  void createInstance(const ContextOptions& options);
  void pickPhysicalDevice(const std::string& wanted);
  void createDevice(const ContextOptions& options);
  void destroy();
  static VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool uploadPool_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceFeatures features_{};
  VkPhysicalDeviceMemoryProperties memoryProperties_{};
  bool echoValidation_ = true;
  mutable std::mutex validationMutex_;
  ValidationReport validation_;
};

}  // namespace shadelab
