#include "core/vulkan/context.h"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/base/errors.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// lavapipe runs in this process and allocates its vertex output per draw.
// With glibc's defaults each large block is mmapped, page-faulted in and
// unmapped again every frame; on a 102,400-triangle mesh that made one frame
// in four take 3x the median (p95 52 ms vs 16 ms, `render dense --frames 150
// --mode unlit`). Keeping freed memory in the heap removes those spikes (p95
// 20 ms) and lowers the median by ~5%. Process-wide, so set here, once, for
// every program that opens a Context (the library's users too).
//
// The same heap then holds lavapipe's device memory, and first touches of it
// dominated the first frame: on the project's VM a 4 KiB page fault is dear,
// and the default scene's shadow maps (seven 2048x2048 depth layers, 117 MB)
// took 406 ms on the first frame against 24 ms redrawn. Marking the heap's
// next 512 MiB MADV_HUGEPAGE (transparent huge pages are "madvise" on
// Debian) makes those faults 2 MiB each: the first PNG of the default scene
// went from 1.12 to 0.50 s (docs/PERFORMANCE.md, "Start-up"). glibc's
// glibc.malloc.hugetlb=1 tunable does the same, but only when set in the
// environment before the process starts. The block is only reserved: freed
// at once into the heap's top (below the trim threshold, so kept), touched
// nowhere but its header, it costs address space, not memory.
void preferHugePagesInHeap() {
  constexpr size_t kReserve = size_t(512) << 20, kHugePage = size_t(2) << 20;
  void* block = std::malloc(kReserve);
  if (!block) return;
  uintptr_t begin = (reinterpret_cast<uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
  uintptr_t end = (reinterpret_cast<uintptr_t>(block) + kReserve) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  std::free(block);
}

void keepFreedMemoryInHeap() {
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    preferHugePagesInHeap();
  });
}

bool layerAvailable(const char* name) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  for (const auto& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

DeviceDescription describe(VkPhysicalDevice physical) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(physical, &properties);
  return {properties.properties.deviceName, driver.driverName, driver.driverInfo,
          properties.properties.apiVersion, properties.properties.deviceType};
}

VkInstance createBareInstance(const std::vector<const char*>& layers,
                              const std::vector<const char*>& extensions, const void* next) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "shadelab";
  app.pEngineName = "shadelab";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, next};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  VK_CHECK(vkCreateInstance(&info, nullptr, &instance));
  return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

}  // namespace

Context::Context(const ContextOptions& options) : echoValidation_(options.echoValidation) {
  if (options.keepFreedMemoryInHeap) keepFreedMemoryInHeap();
  try {
    createInstance(options);
    pickPhysicalDevice(options.deviceName);
    createDevice(options);
  } catch (...) {
    destroy();  // the destructor does not run when a constructor throws
    throw;
  }
}

Context::~Context() {
  destroy();
}

ValidationReport Context::shutdown() {
  destroy();  // the messenger outlives the device, so its teardown messages count
  return validationReport();
}

void Context::destroy() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (uploadPool_) vkDestroyCommandPool(device_, uploadPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

void Context::createInstance(const ContextOptions& options) {
  std::vector<const char*> layers;
  std::vector<const char*> extensions = options.instanceExtensions;
  if (options.validation) {
    if (!layerAvailable(kValidationLayer))
      throw VulkanError(
          "validation requested but VK_LAYER_KHRONOS_validation is not installed "
          "(Debian package vulkan-validationlayers)");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &Context::onValidationMessage;
  messengerInfo.pUserData = this;
  // Synchronization validation catches missing barriers, which core
  // validation does not.
  VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &messengerInfo};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;

  instance_ = createBareInstance(layers, extensions, options.validation ? &features : nullptr);
  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
  }
}

void Context::pickPhysicalDevice(const std::string& wanted) {
  std::string seen;
  for (VkPhysicalDevice candidate : physicalDevices(instance_)) {
    DeviceDescription info = describe(candidate);
    seen += "\n  " + info.name;
    if (info.apiVersion < VK_API_VERSION_1_3) continue;
    if (!wanted.empty() && info.name.find(wanted) == std::string::npos) continue;
    physicalDevice_ = candidate;
    break;
  }
  if (!physicalDevice_) {
    if (!wanted.empty())
      throw InputError("--device: no Vulkan 1.3 device whose name contains '" + wanted +
                       "'; devices found:" + (seen.empty() ? " none" : seen));
    throw VulkanError("no Vulkan 1.3 device found (install mesa-vulkan-drivers for lavapipe)");
  }
  vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
  vkGetPhysicalDeviceFeatures(physicalDevice_, &features_);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memoryProperties_);
}

void Context::createDevice(const ContextOptions& options) {
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &familyCount, families.data());
  bool found = false;
  for (uint32_t i = 0; i < familyCount && !found; ++i) {
    // Graphics with timestamps: one queue does drawing, copies and timing.
    if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && families[i].timestampValidBits > 0) {
      queueFamily_ = i;
      found = true;
    }
  }
  if (!found) throw VulkanError("device has no graphics queue with timestamp support");

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkPhysicalDeviceVulkan13Features features13{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  features13.dynamicRendering = VK_TRUE;
  features13.synchronization2 = VK_TRUE;
  // glslang's SPIR-V 1.6 compute shaders declare their group size with LocalSizeId.
  features13.maintenance4 = VK_TRUE;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13};
  // Flat shading uses a geometry shader; the rest are optional and used when offered.
  if (!features_.geometryShader) throw VulkanError("device lacks geometryShader (flat shading)");
  features.features.geometryShader = VK_TRUE;
  features.features.samplerAnisotropy = features_.samplerAnisotropy;
  features.features.fillModeNonSolid = features_.fillModeNonSolid;
  features.features.pipelineStatisticsQuery = features_.pipelineStatisticsQuery;
  features.features.depthClamp =
      features_.depthClamp;  // shadow casters before the light's near plane

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = uint32_t(options.deviceExtensions.size());
  info.ppEnabledExtensionNames = options.deviceExtensions.data();
  VK_CHECK(vkCreateDevice(physicalDevice_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &uploadPool_));
}

DeviceDescription Context::description() const {
  return describe(physicalDevice_);
}

std::vector<DeviceDescription> Context::listDevices() {
  VkInstance instance = createBareInstance({}, {}, nullptr);
  std::vector<DeviceDescription> result;
  for (VkPhysicalDevice device : physicalDevices(instance)) result.push_back(describe(device));
  vkDestroyInstance(instance, nullptr);
  return result;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onValidationMessage(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<Context*>(user);
  bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  std::string message = data && data->pMessage ? data->pMessage : "(no message)";
  {
    std::lock_guard lock(self->validationMutex_);
    (error ? self->validation_.errors : self->validation_.warnings)++;
    self->validation_.messages.push_back(message);
  }
  if (self->echoValidation_)
    std::fprintf(stderr, "validation %s: %s\n", error ? "error" : "warning", message.c_str());
  return VK_FALSE;
}

ValidationReport Context::validationReport() const {
  std::lock_guard lock(validationMutex_);
  return validation_;
}

void Context::resetValidationReport() {
  std::lock_guard lock(validationMutex_);
  validation_ = {};
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const {
  for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memoryProperties_.memoryTypes[i].propertyFlags & flags) == flags)
      return i;
  throw VulkanError("no memory type with the requested properties");
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = uploadPool_;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(device_, &allocInfo, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  VK_CHECK(vkQueueSubmit2(queue_, 1, &submit, VK_NULL_HANDLE));
  VK_CHECK(vkQueueWaitIdle(queue_));
  vkFreeCommandBuffers(device_, uploadPool_, 1, &cmd);
}

void Context::waitIdle() const {
  VK_CHECK(vkDeviceWaitIdle(device_));
}

}  // namespace shadelab
