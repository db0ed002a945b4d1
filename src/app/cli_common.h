#pragma once
// Helpers shared by the subcommands: option parsing that reports bad values
// as InputError, and the Vulkan context every command opens the same way.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/base/errors.h"
#include "core/base/files.h"
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

// Throws InputError when `output`, a file the command writes (`what` says
// which), is the file `input` names (a scene or model; a built-in name is
// no file): compare my.json -o my.png once wrote its numbers over my.json.
void checkNotInput(const std::filesystem::path& output, const std::string& input,
                   const std::string& what);

// CLI::Range for a floating-point option that also refuses NaN, which passes
// CLI::Range (every comparison with NaN is false), and infinities.
CLI::Validator finiteRange(double min, double max);

// "a,b,c" -> {"a", "b", "c"}: a comma-separated list option's entries, in
// order. Throws InputError naming the option for an empty entry (",a",
// "a,,b", "a,") or one listed twice ("phong,phong" measured it twice).
std::vector<std::string> splitList(const std::string& text, const std::string& option);

// "0.5,1,2" -> {0.5, 1, 2}: splitList's entries read as finite numbers from
// `min` to `max` (whole numbers when `integers`); throws InputError naming the entry and what
// `expected` says.
std::vector<double> parseNumberList(const std::string& text, const std::string& option, double min,
                                    double max, bool integers, const std::string& expected);

// Throws InputError naming the option when a parsed list holds a value twice
// (for lists CLI11 splits itself, and entries that differ only in spelling).
template <typename T>
void requireDistinct(const std::vector<T>& values, const std::string& option) {
  for (size_t i = 0; i < values.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (values[j] == values[i])
        throw InputError(option + ": entries " + std::to_string(j + 1) + " and " +
                         std::to_string(i + 1) + " are the same value; list each once");
}

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

// Throws InputError naming DIR unless `firstFile` can be written in it: DIR
// is a writable folder, or does not exist and its parent is writable.
void checkOutputFolder(const std::filesystem::path& folder, const std::string& firstFile);
// checkOutputFolder, then creates DIR if needed.
void prepareOutputFolder(const std::filesystem::path& folder, const std::string& firstFile);

// Prints sceneWarnings (scene.h) to stderr as "shadelab: warning: ...".
void printSceneWarnings(const Scene& scene, bool rasteriser);
// Prints depthPrecisionWarning (depth.h) for the scene's camera and bounds
// the same way: a near plane that leaves `depth` unable to draw the scene.
void printDepthWarning(const Scene& scene, DepthMode depth);

std::unique_ptr<Context> openContext(const GlobalOptions& global);
// After a command, once every Vulkan object of it is destroyed: with
// validation on, shuts the context down (its teardown messages count too)
// and any message turns success into exit 1.
int finishWithValidation(Context& context, int exitCode);

// A command's outputs as one: each file is written whole to a hidden name
// beside its target (".NAME-staged-RANDOM.EXT", the extension kept for the
// writers that go by it), and only keep() renames them all into place. A
// run that fails before keep() removes what it staged, and the folder when
// it made it: nothing of a failed command stays on disk, and the files of
// an earlier run under the same names are left as they were. The same holds
// when SIGINT, SIGTERM or SIGHUP end the process (RemovedOnSignal, files.h).
class OutputGroup {
 public:
  // `folder`: made on the first write if it does not exist (empty: none).
  explicit OutputGroup(std::filesystem::path folder = {}) : folder_(std::move(folder)) {}
  OutputGroup(const OutputGroup&) = delete;
  OutputGroup& operator=(const OutputGroup&) = delete;
  ~OutputGroup();
  // Checks that `path` can be written (checkWritableFolder: its folder
  // exists and is writable, it is not a folder), then runs `write(staged)`,
  // which writes the file that becomes `path` at keep().
  void add(const std::filesystem::path& path,
           const std::function<void(const std::filesystem::path& staged)>& write);
  // All written: renames each staged file to its target. Throws InputError
  // naming the file if a rename fails: the files renamed before it are put
  // back as the earlier run left them (kept aside as hard links until the
  // last rename) and the rest of the staged files are removed. (A signal in
  // the microseconds of the renames can still leave a mix.)
  void keep();

 private:
  std::filesystem::path folder_;
  bool madeFolder_ = false;
  RemovedOnSignal folderGuard_;
  bool kept_ = false;
  struct Staged {
    std::filesystem::path target;
    std::filesystem::path staged;
    RemovedOnSignal guard;
  };
  std::vector<Staged> staged_;
  size_t renamed_ = 0;
};

}  // namespace shadelab
