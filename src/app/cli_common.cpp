#include "app/cli_common.h"

#include <charconv>
#include <cstdio>
#include <regex>
#include <sstream>

#include "core/base/errors.h"
#include "core/base/files.h"

namespace shadelab {

Size parseSize(const std::string& text, const std::string& option) {
  static const std::regex pattern(R"((\d{1,6})x(\d{1,6}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
    throw InputError(option + " '" + text + "': expected WIDTHxHEIGHT, e.g. 1280x720");
  Size size;
  std::from_chars(&*match[1].first, &*match[1].first + match[1].length(), size.width);
  std::from_chars(&*match[2].first, &*match[2].first + match[2].length(), size.height);
  if (size.width == 0 || size.height == 0)
    throw InputError(option + " '" + text + "': width and height must be at least 1");
  return size;
}

std::vector<ShadingModel> parseShadingModelList(const std::string& text,
                                                const std::string& option) {
  std::vector<ShadingModel> models;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
    models.push_back(parseNamed(kShadingModelNames, item, option));
  if (models.empty()) throw InputError(option + " '" + text + "': expected at least one model");
  return models;
}

void prepareOutputFolder(const std::filesystem::path& folder, const std::string& firstFile) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(folder, error)) {
    checkWritableFolder(folder / firstFile);
    return;
  }
  if (fs::exists(folder, error))
    throw InputError("output '" + folder.string() + "' exists and is not a folder");
  checkWritableFolder(folder);  // the parent
  if (!fs::create_directory(folder, error))
    throw InputError("cannot create output folder '" + folder.string() + "': " + error.message());
}

void printSceneWarnings(const Scene& scene, bool rasteriser) {
  for (const std::string& warning : sceneWarnings(scene, rasteriser))
    std::fprintf(stderr, "shadelab: warning: %s\n", warning.c_str());
}

std::unique_ptr<Context> openContext(const GlobalOptions& global) {
  ContextOptions options;
  options.validation = global.validate;
  options.deviceName = global.device;
  return std::make_unique<Context>(options);
}

int finishWithValidation(const Context& context, int exitCode) {
  if (!context.validationEnabled()) return exitCode;
  ValidationReport report = context.validationReport();
  if (report.total() == 0) return exitCode;
  std::fprintf(stderr, "shadelab: the validation layer reported %u error(s) and %u warning(s)\n",
               report.errors, report.warnings);
  return exitCode == 0 ? 1 : exitCode;
}

}  // namespace shadelab
