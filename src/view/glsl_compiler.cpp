#include "view/glsl_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <string_view>

#include "core/base/errors.h"
#include "core/base/files.h"

namespace shadelab {
namespace {

// Only a regular file of sane size: a FIFO named like a shader hung the
// reload, a link to /dev/zero grew without end.
bool readText(const std::filesystem::path& path, std::string& text) {
  try {
    text = readInputFile(path, "shader source", kMaxTextInputBytes);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// Resolves `#include "x"` against one folder, as the build's -I does.
class FolderIncluder : public glslang::TShader::Includer {
 public:
  explicit FolderIncluder(std::filesystem::path directory) : directory_(std::move(directory)) {}

  IncludeResult* includeLocal(const char* headerName, const char*, size_t) override {
    auto text = std::make_unique<std::string>();
    std::filesystem::path path = directory_ / headerName;
    if (!readText(path, *text)) {
      *text = "cannot open include file " + path.string();
      return keep(std::move(text), "");
    }
    return keep(std::move(text), path.string());
  }
  IncludeResult* includeSystem(const char* headerName, const char* includer,
                               size_t depth) override {
    return includeLocal(headerName, includer, depth);
  }
  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    texts_.erase(result);
    delete result;
  }

 private:
  IncludeResult* keep(std::unique_ptr<std::string> text, const std::string& resolved) {
    auto* result = new IncludeResult(resolved, text->data(), text->size(), nullptr);
    texts_[result] = std::move(text);
    return result;
  }
  std::filesystem::path directory_;
  std::map<IncludeResult*, std::unique_ptr<std::string>> texts_;
};

bool stageOf(VkShaderStageFlagBits vulkanStage, EShLanguage& stage) {
  switch (vulkanStage) {
    case VK_SHADER_STAGE_VERTEX_BIT:
      stage = EShLangVertex;
      return true;
    case VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT:
      stage = EShLangTessControl;
      return true;
    case VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT:
      stage = EShLangTessEvaluation;
      return true;
    case VK_SHADER_STAGE_GEOMETRY_BIT:
      stage = EShLangGeometry;
      return true;
    case VK_SHADER_STAGE_FRAGMENT_BIT:
      stage = EShLangFragment;
      return true;
    case VK_SHADER_STAGE_COMPUTE_BIT:
      stage = EShLangCompute;
      return true;
    default:
      return false;
  }
}

}  // namespace

GlslCompileResult compileGlsl(const std::filesystem::path& directory,
                              const ShaderVariant& variant) {
  // glslang keeps process-wide tables: initialise once, never finalise.
  static std::once_flag initialised;
  std::call_once(initialised, [] { glslang::InitializeProcess(); });

  GlslCompileResult result;
  std::filesystem::path path = directory / variant.source;
  EShLanguage stage;
  if (!stageOf(variant.stage, stage)) {
    result.log = path.string() +
                 ": not a vertex, tessellation, geometry, fragment or compute "
                 "stage";
    return result;
  }
  std::string source;
  if (!readText(path, source)) {
    result.log = path.string() + ": cannot read the file";
    return result;
  }
  glslang::TShader shader(stage);
  const char* text = source.c_str();
  std::string pathName = path.string();
  const char* fileName = pathName.c_str();
  shader.setStringsWithLengthsAndNames(&text, nullptr, &fileName, 1);
  // What glslangValidator makes of -DNAME: one line of a preamble that glslang
  // reads after the #version line.
  std::string preamble;
  for (std::string_view define : variant.defines)
    preamble += "#define " + std::string(define) + "\n";
  shader.setPreamble(preamble.c_str());
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
  FolderIncluder includer(directory);
  auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 100, false, messages, includer)) {
    result.log = shader.getInfoLog();
    return result;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    result.log = program.getInfoLog();
    return result;
  }
  glslang::SpvOptions options;
  options.disableOptimizer = true;
  glslang::GlslangToSpv(*program.getIntermediate(stage), result.spirv, &options);
  return result;
}

}  // namespace shadelab
