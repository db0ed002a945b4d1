#include "app/cli_common.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <regex>
#include <sstream>
#include <system_error>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/names.h"
#include "core/scene/gltf_loader.h"

namespace shadelab {
namespace {
// The largest width or height any command accepts: lavapipe's
// maxImageDimension2D and the tracer's limit. (A device with a smaller limit
// is still refused by Renderer::validate, after the device is open.)
constexpr uint32_t kMaxImageSide = 16384;
}  // namespace

void checkNotInput(const std::filesystem::path& output, const std::string& input,
                   const std::string& what) {
  std::error_code error;
  if (!input.empty() && std::filesystem::equivalent(output, input, error))
    throw InputError("output '" + output.string() + "' (" + what + ") is the input '" + input +
                     "': it would be overwritten; expected another output name");
}

CLI::Validator finiteRange(double min, double max) {
  std::ostringstream description;
  description << "FLOAT in [" << min << " - " << max << "]";
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        double value = 0.0;
        // Values that are not numbers at all are CLI11's own conversion error.
        if (!CLI::detail::lexical_cast(text, value)) return {};
        if (std::isfinite(value) && value >= min && value <= max) return {};
        std::ostringstream message;
        message << "Value " << text << " not in range [" << min << " - " << max << "]";
        return message.str();
      },
      description.str());
}

Size parseSize(const std::string& text, const std::string& option) {
  static const std::regex pattern(R"((\d{1,6})x(\d{1,6}))");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
    throw InputError(option + " '" + text + "': expected WIDTHxHEIGHT, e.g. 1280x720");
  Size size;
  std::from_chars(&*match[1].first, &*match[1].first + match[1].length(), size.width);
  std::from_chars(&*match[2].first, &*match[2].first + match[2].length(), size.height);
  if (size.width == 0 || size.height == 0 || size.width > kMaxImageSide ||
      size.height > kMaxImageSide)
    throw InputError(option + " '" + text + "': width and height must be 1.." +
                     std::to_string(kMaxImageSide));
  return size;
}

std::vector<std::string> splitList(const std::string& text, const std::string& option) {
  std::vector<std::string> items = splitFields(text);
  if (items.empty()) items.emplace_back();
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].empty())
      throw InputError(option + " '" + text + "': entry " + std::to_string(i + 1) +
                       " is empty; expected a comma-separated list");
    for (size_t j = 0; j < i; ++j)
      if (items[j] == items[i])
        throw InputError(option + " '" + text + "': '" + items[i] +
                         "' is listed twice; list each once");
  }
  return items;
}

std::vector<double> parseNumberList(const std::string& text, const std::string& option, double min,
                                    double max, bool integers, const std::string& expected) {
  std::vector<double> values;
  for (const std::string& item : splitList(text, option)) {
    double value = 0.0;
    const char* end = item.data() + item.size();
    auto [stop, error] = std::from_chars(item.data(), end, value);
    if (error != std::errc() || stop != end || !std::isfinite(value) || value < min ||
        value > max || (integers && value != std::floor(value)))
      throw InputError(option + " '" + item + "': expected " + expected);
    values.push_back(value);
  }
  requireDistinct(values, option);
  return values;
}

std::vector<ShadingModel> parseShadingModelList(const std::string& text,
                                                const std::string& option) {
  std::vector<ShadingModel> models;
  for (const std::string& item : splitList(text, option))
    models.push_back(parseNamed(kShadingModelNames, item, option));
  return models;
}

void checkOutputFolder(const std::filesystem::path& folder, const std::string& firstFile) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(folder, error)) {
    checkWritableFolder(folder / firstFile);
    return;
  }
  if (fs::exists(folder, error))
    throw InputError("output '" + folder.string() + "' exists and is not a folder");
  checkWritableFolder(folder);  // the parent
}

void prepareOutputFolder(const std::filesystem::path& folder, const std::string& firstFile) {
  namespace fs = std::filesystem;
  checkOutputFolder(folder, firstFile);
  std::error_code error;
  if (!fs::is_directory(folder, error) && !fs::create_directory(folder, error))
    throw InputError("cannot create output folder '" + folder.string() + "': " + error.message());
}

void printSceneWarnings(const Scene& scene, bool rasteriser) {
  for (const std::string& warning : sceneWarnings(scene, rasteriser))
    std::fprintf(stderr, "shadelab: warning: %s\n", warning.c_str());
}

void printDepthWarning(const Scene& scene, DepthMode depth) {
  const Camera& camera = scene.camera;
  Bounds bounds = sceneBounds(scene);
  glm::vec3 sight = glm::normalize(camera.at - camera.eye);
  double farthest = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    glm::vec3 point{corner & 1 ? bounds.max.x : bounds.min.x,
                    corner & 2 ? bounds.max.y : bounds.min.y,
                    corner & 4 ? bounds.max.z : bounds.min.z};
    farthest = std::max(farthest, double(glm::dot(point - camera.eye, sight)));
  }
  if (std::optional<std::string> warning = depthPrecisionWarning(camera, depth, farthest))
    std::fprintf(stderr, "shadelab: warning: %s\n", warning->c_str());
}

std::unique_ptr<Context> openContext(const GlobalOptions& global) {
  ContextOptions options;
  options.validation = global.validate;
  options.deviceName = global.device;
  return std::make_unique<Context>(options);
}

int finishWithValidation(Context& context, int exitCode) {
  if (!context.validationEnabled()) return exitCode;
  ValidationReport report = context.shutdown();
  if (report.total() == 0) return exitCode;
  std::fprintf(stderr, "shadelab: the validation layer reported %u error(s) and %u warning(s)\n",
               report.errors, report.warnings);
  return exitCode == 0 ? 1 : exitCode;
}

OutputGroup::~OutputGroup() {
  if (kept_) return;
  std::error_code ignored;
  for (size_t i = renamed_; i < staged_.size(); ++i)
    std::filesystem::remove(staged_[i].staged, ignored);
  // Only if empty: a failed rename in keep() leaves the files before it.
  if (madeFolder_) std::filesystem::remove(folder_, ignored);
}

void OutputGroup::add(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& staged)>& write) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!folder_.empty() && !madeFolder_ && !fs::is_directory(folder_, error)) {
    if (!fs::create_directory(folder_, error))
      throw InputError("cannot create output folder '" + folder_.string() +
                       "': " + error.message());
    madeFolder_ = true;
    folderGuard_ = RemovedOnSignal(folder_, true);
  }
  checkWritableFolder(path);
  std::optional<std::string> random = randomHex();
  if (!random)
    throw InputError("cannot write '" + path.string() + "': no random bytes for a staging name");
  std::string name = ".";
  name += path.stem().string();
  name += "-staged-";
  name += *random;
  name += path.extension().string();
  fs::path staged = path.parent_path() / name;
  staged_.push_back({path, staged, RemovedOnSignal(staged)});
  try {
    write(staged);
  } catch (const InputError& failure) {
    // The message names the file the user asked for, not its staging name.
    std::string what = failure.what();
    const std::string hidden = staged.string();
    for (size_t at = what.find(hidden); at != std::string::npos; at = what.find(hidden, at))
      what.replace(at, hidden.size(), path.string());
    throw InputError(what);
  }
}

void OutputGroup::keep() {
  namespace fs = std::filesystem;
  // An earlier run's file under a target's name is kept aside (a hard link
  // under a hidden name) until every staged file is in place: a rename that
  // fails part-way puts the earlier files back, so the targets hold all of
  // this run's files or none. Where no link can be made (a file system
  // without them) the earlier file is replaced unguarded.
  std::vector<fs::path> aside(staged_.size());
  std::vector<bool> earlier(staged_.size(), false);  // a file was there before
  std::vector<RemovedOnSignal> asideGuards;
  auto removeAsides = [&] {
    std::error_code ignored;
    for (const fs::path& path : aside)
      if (!path.empty()) fs::remove(path, ignored);
  };
  for (size_t i = renamed_; i < staged_.size(); ++i) {
    struct stat info {};
    if (::lstat(staged_[i].target.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) continue;
    earlier[i] = true;
    std::optional<std::string> random = randomHex();
    if (!random) continue;
    fs::path path = staged_[i].target.parent_path() /
                    ("." + staged_[i].target.filename().string() + "-previous-" + *random);
    asideGuards.emplace_back(path);
    if (::link(staged_[i].target.c_str(), path.c_str()) == 0) aside[i] = path;
  }
  const size_t first = renamed_;
  for (; renamed_ < staged_.size(); ++renamed_) {
    const Staged& file = staged_[renamed_];
    if (::rename(file.staged.c_str(), file.target.c_str()) != 0) {
      const int error = errno;  // before any allocation below can change it
      // Back as they were: the earlier files over this run's, this run's
      // new names removed.
      // (An earlier file that could not be linked aside is lost: replaced.)
      for (size_t i = first; i < renamed_; ++i) {
        if (!aside[i].empty() && ::rename(aside[i].c_str(), staged_[i].target.c_str()) == 0)
          aside[i].clear();
        else if (!earlier[i])
          ::unlink(staged_[i].target.c_str());
      }
      removeAsides();
      throw InputError("cannot write '" + file.target.string() +
                       "': " + std::generic_category().message(error));
    }
    staged_[renamed_].guard.release();
  }
  removeAsides();
  folderGuard_.release();
  kept_ = true;
}

}  // namespace shadelab
