#include "app/cli_common.h"

#include <charconv>
#include <cstdio>
#include <regex>
#include <sstream>

#include "core/base/errors.h"

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

void ShadowOptions::add(CLI::App* command) {
  command
      ->add_option("--shadows", method,
                   namedHelp("Shadow maps and their filter (off: no shadows)", kShadowMethodNames))
      ->capture_default_str();
  command->add_option("--shadow-size", size, "Shadow map size in texels (square)")
      ->capture_default_str();
  command
      ->add_option("--shadow-bias", bias,
                   "Constant shadow bias towards the light, in shadow-map texels (0..64)")
      ->capture_default_str();
  command
      ->add_option("--shadow-slope-bias", slopeBias,
                   "Slope-scaled shadow bias: texels times tan(angle of N and L) (0..64)")
      ->capture_default_str();
  command
      ->add_option("--shadow-normal-offset", normalOffset,
                   "Normal-offset shadow bias: texels along the normal times sin(angle) (0..64)")
      ->capture_default_str();
}

void ShadowOptions::apply(FrameSettings& settings) const {
  settings.shadows = parseNamed(kShadowMethodNames, method, "--shadows");
  if (size < 1 || size > 65536)
    throw InputError("--shadow-size " + std::to_string(size) +
                     ": expected a map size from 1 to the device's largest 2D image (16384 "
                     "on lavapipe)");
  settings.shadowMapSize = uint32_t(size);
  for (auto [option, value] :
       {std::pair{"--shadow-bias", bias}, std::pair{"--shadow-slope-bias", slopeBias},
        std::pair{"--shadow-normal-offset", normalOffset}})
    if (!(value >= 0.0f && value <= kMaxShadowBias)) {
      std::ostringstream text;
      text << option << " " << value << ": expected 0 to " << kMaxShadowBias << " texels";
      throw InputError(text.str());
    }
  settings.shadowBias = {bias, slopeBias, normalOffset};
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
