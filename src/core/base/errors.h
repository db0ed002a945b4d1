#pragma once
// The three error tiers (STYLE.md): programmer errors assert; Vulkan call
// failures throw VulkanError from VK_CHECK; bad user input (files, scenes,
// options) throws InputError, which the CLI turns into exit code 2.
#include <stdexcept>
#include <string>

namespace shadelab {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace shadelab
