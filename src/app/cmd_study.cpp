// shadelab study [NAME] -o DIR: runs one study of the registry
// (measure/study.h) into DIR and prints its table; without NAME, lists them.
#include <cstdio>
#include <memory>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/base/errors.h"
#include "measure/study.h"

namespace shadelab {
namespace {

struct StudyCommandOptions {
  std::string name;
  std::string output;
  std::string size;  // empty: the study's default
};

int listStudies() {
  std::printf("studies (shadelab study NAME -o DIR):\n");
  for (const Study& study : studies())
    std::printf("  %-18s %s\n", std::string(study.name).c_str(),
                std::string(study.summary).c_str());
  return 0;
}

int runStudy(const StudyCommandOptions& options, const GlobalOptions& global) {
  if (options.name.empty()) return listStudies();
  const Study& study = findStudy(options.name);
  if (options.output.empty()) throw InputError("study " + options.name + ": -o DIR is required");
  StudyOptions run{options.output, study.defaultWidth, study.defaultHeight};
  if (!options.size.empty()) {
    Size size = parseSize(options.size, "--size");
    run.width = size.width;
    run.height = size.height;
  }
  prepareOutputFolder(run.output, std::string(study.name) + ".csv");

  // Opened on first use: studies of the CPU tracer open no device.
  std::unique_ptr<Context> context;
  std::unique_ptr<Renderer> renderer;
  StudyServices services;
  services.renderer = [&]() -> Renderer& {
    if (!renderer) {
      context = openContext(global);
      renderer = std::make_unique<Renderer>(*context);
    }
    return *renderer;
  };
  services.progress = [](const std::string& line) { std::fprintf(stderr, "  %s\n", line.c_str()); };
  std::fprintf(stderr, "study %s at %ux%u: %s\n", options.name.c_str(), run.width, run.height,
               std::string(study.summary).c_str());
  StudyResult result = study.run(run, services);
  renderer.reset();
  std::printf("%s", result.report.c_str());
  std::printf("wrote into %s:", run.output.c_str());
  for (const std::string& file : result.files) std::printf(" %s", file.c_str());
  std::printf("\n");
  return context ? finishWithValidation(*context, 0) : 0;
}

}  // namespace

CommandRunner addStudyCommand(CLI::App& app, const GlobalOptions& global) {
  auto options = std::make_shared<StudyCommandOptions>();
  std::string names;
  for (const Study& study : studies())
    names += (names.empty() ? "" : ", ") + std::string(study.name);
  CLI::App* command = app.add_subcommand(
      "study", "Measure one seed claim or failure mode into DIR: images, CSV and a chart (" +
                   names + "); without NAME, list the studies");
  command->add_option("name", options->name, "The study: " + names);
  command->add_option("-o,--output", options->output,
                      "Folder for the study's images, CSV and chart (created if needed)");
  command->add_option("--size", options->size,
                      "Image size WIDTHxHEIGHT (default: the study's own, e.g. 640x360)");
  return [options, &global] { return runStudy(*options, global); };
}

}  // namespace shadelab
