#pragma once
// Helpers shared by the subcommands: option parsing that reports bad values
// as InputError, and the Vulkan context every command opens the same way.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/scene/scene.h"
#include "core/scene/shading.h"
#include "core/vulkan/context.h"
#include "core/vulkan/depth.h"

namespace shadelab {

struct Size {
  uint32_t width = 0;
  uint32_t height = 0;
};
// "1280x720" -> {1280, 720}; throws InputError naming the option and value.
Size parseSize(const std::string& text, const std::string& option);

// "flat,phong" -> models, in order; throws InputError naming a bad entry.
std::vector<ShadingModel> parseShadingModelList(const std::string& text, const std::string& option);

// An option's help text ending in the names its table accepts:
// "Depth buffer: d16, d24, d32f, reversed". Its value is read with
// parseNamed(table, text, "--option") (names.h), so every bad value gets one
// kind of message and exit code.
template <typename E, size_t N>
std::string namedHelp(const std::string& what, const NameTable<E, N>& table) {
  return what + ": " + joinNames(namesOf(table));
}

// Creates the output folder DIR if needed (its parent must exist) and checks
// that `firstFile` can be written in it; throws InputError naming it.
void prepareOutputFolder(const std::filesystem::path& folder, const std::string& firstFile);

// Prints sceneWarnings (scene.h) to stderr as "shadelab: warning: ...".
void printSceneWarnings(const Scene& scene, bool rasteriser);

std::unique_ptr<Context> openContext(const GlobalOptions& global);
// After a command: with validation on, any message turns success into exit 1.
int finishWithValidation(const Context& context, int exitCode);

}  // namespace shadelab
