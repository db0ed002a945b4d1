#pragma once
// GLSL to SPIR-V at run time (glslang), for reloading shaders from disk while
// the viewer runs. The build compiles the same files with glslangValidator;
// both produce the same SPIR-V.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab {

struct GlslCompileResult {
  std::vector<uint32_t> spirv;  // empty on failure
  std::string log;              // the compiler's messages, naming file and line
  bool ok() const { return !spirv.empty(); }
};

// Compiles `directory`/`name` (stage from the extension: .vert .geom .frag
// .comp .tesc .tese) for Vulkan 1.3; #include resolves inside `directory`.
GlslCompileResult compileGlslFile(const std::filesystem::path& directory, const std::string& name);

}  // namespace shadelab
