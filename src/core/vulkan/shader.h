#pragma once
#include <span>
#include <string_view>

#include "core/vulkan/resources.h"
#include "core/vulkan/shader_table.h"

namespace shadelab {

// SPIR-V compiled at build time and linked into the binary (cmake/shaders.cmake),
// looked up by its name in the shader table, e.g. "forward_gouraud.vert".
// Empty if unknown.
std::span<const uint32_t> embeddedSpirv(std::string_view name);

ShaderModule createShaderModule(VkDevice device, std::span<const uint32_t> spirv);
// Asserts the shader exists: a missing name is a build error, not user input.
ShaderModule loadShader(VkDevice device, std::string_view name);

}  // namespace shadelab
