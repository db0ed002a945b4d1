#include <cstdio>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/scene/scene.h"
#include "core/scene/shading.h"
#include "core/vulkan/depth.h"

namespace shadelab {
namespace {

const char* deviceTypeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU (software)";
    default:
      return "other";
  }
}

std::string versionString(uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
         std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

int runInfo(const GlobalOptions& global) {
  for (const DeviceDescription& device : Context::listDevices())
    std::printf("device available: %s (Vulkan %s, %s)\n", device.name.c_str(),
                versionString(device.apiVersion).c_str(), deviceTypeName(device.type));
  std::unique_ptr<Context> context = openContext(global);
  DeviceDescription device = context->description();
  const VkPhysicalDeviceProperties& properties = context->properties();
  const VkPhysicalDeviceFeatures& features = context->features();
  std::printf("device:          %s (%s)\n", device.name.c_str(), deviceTypeName(device.type));
  std::printf("driver:          %s, %s\n", device.driverName.c_str(), device.driverInfo.c_str());
  std::printf("vulkan:          %s\n", versionString(device.apiVersion).c_str());
  std::printf("validation:      %s\n", context->validationEnabled() ? "on" : "off");
  std::printf("features used:   dynamic rendering, synchronization2, geometry shader (flat)\n");
  std::printf(
      "optional:        sampler anisotropy %s (max %.0f), wireframe %s, "
      "pipeline statistics %s\n",
      features.samplerAnisotropy ? "yes" : "no", properties.limits.maxSamplerAnisotropy,
      features.fillModeNonSolid ? "yes" : "no", features.pipelineStatisticsQuery ? "yes" : "no");
  std::string depthModes;
  for (DepthMode mode : valuesOf(kDepthModeNames)) {
    VkFormatProperties format;
    vkGetPhysicalDeviceFormatProperties(context->physicalDevice(), depthFormat(mode), &format);
    bool usable = format.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
    depthModes += " " + std::string(depthModeName(mode)) + (usable ? "" : " (unsupported)");
  }
  std::printf("depth modes:    %s\n", depthModes.c_str());
  std::printf("timestamps:      %.3f ns per tick\n", properties.limits.timestampPeriod);
  std::printf("max image size:  %u\n", properties.limits.maxImageDimension2D);
  std::string scenes, models;
  for (const std::string& name : builtinSceneNames()) scenes += " " + name;
  models = " " + joinNames(namesOf(kShadingModelNames), " ");
  std::printf("built-in scenes:%s\n", scenes.c_str());
  std::printf("shading models: %s\n", models.c_str());
  return finishWithValidation(*context, 0);
}

}  // namespace

CommandRunner addInfoCommand(CLI::App& app, const GlobalOptions& global) {
  app.add_subcommand("info", "Print the Vulkan device, driver and the features shadelab uses");
  return [&global] { return runInfo(global); };
}

}  // namespace shadelab
