#pragma once
// GLSL to SPIR-V at run time (glslang), for reloading shaders from disk while
// the viewer runs. The build compiles the same shader table rows with
// glslangValidator; both produce the same SPIR-V.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/vulkan/shader_table.h"

namespace shadelab {

struct GlslCompileResult {
  std::vector<uint32_t> spirv;  // empty on failure
  std::string log;              // the compiler's messages, naming file and line
  bool ok() const { return !spirv.empty(); }
};

// Compiles `directory`/`variant.source` as `variant.stage` for Vulkan 1.3,
// with `#define NAME` for each of its defines (glslangValidator's -D);
// #include resolves inside `directory`.
GlslCompileResult compileGlsl(const std::filesystem::path& directory, const ShaderVariant& variant);

}  // namespace shadelab
