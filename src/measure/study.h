#pragma once
// Studies: each measures one seed claim or known failure of a technique and
// writes its evidence (images, a CSV and a chart) into a folder. There is one
// registry, studies(); a study is a row of it with its code in
// study_<name>.cpp. `shadelab study NAME -o DIR` runs one.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "passes/renderer.h"

namespace shadelab {

struct StudyOptions {
  std::filesystem::path output;  // an existing, writable folder
  uint32_t width = 0;            // 0: the study's default size
  uint32_t height = 0;
};

// What a study may use. The renderer is opened on first use, so a study of
// the CPU tracer alone opens no Vulkan device; progress lines go to stderr.
struct StudyServices {
  std::function<Renderer&()> renderer;
  std::function<void(const std::string&)> progress;
};

struct StudyResult {
  std::string report;              // the table printed to stdout
  std::vector<std::string> files;  // written, relative to the output folder
};

struct Study {
  std::string_view name;
  std::string_view summary;  // one line for `shadelab study`
  uint32_t defaultWidth;
  uint32_t defaultHeight;
  StudyResult (*run)(const StudyOptions& options, const StudyServices& services);
};

const std::vector<Study>& studies();
// Throws InputError naming `name` and listing the studies.
const Study& findStudy(const std::string& name);

}  // namespace shadelab
