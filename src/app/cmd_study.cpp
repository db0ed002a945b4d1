// shadelab study [NAME] -o DIR: runs one study of the registry
// (measure/study.h) into DIR and prints its table; without NAME, lists them.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/json_output.h"
#include "app/progress.h"
#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/names.h"
#include "measure/study.h"

namespace shadelab {
namespace {

struct StudyCommandOptions {
  std::string name;
  std::string output;
  std::string size;  // empty: the study's default
  JsonOutput json;
};

int listStudies(const JsonOutput& json) {
  FILE* out = json.human();
  std::fprintf(out, "studies (shadelab study NAME -o DIR):\n");
  nlohmann::json list = nlohmann::json::array();
  for (const Study& study : studies()) {
    std::fprintf(out, "  %-18s %s\n", std::string(study.name).c_str(),
                 std::string(study.summary).c_str());
    list.push_back({{"name", std::string(study.name)}, {"summary", std::string(study.summary)}});
  }
  json.emit("study", {{"studies", list}});
  return 0;
}

// A study's CSV (its measurements, one row per line, a header, no quoted
// fields) as rows of objects keyed by the header: numbers as numbers.
nlohmann::json csvRows(const std::filesystem::path& path) {
  std::stringstream text(readInputFile(path, "study output", kMaxTextInputBytes));
  std::string line;
  std::getline(text, line);
  std::vector<std::string> header = splitFields(line);
  nlohmann::json rows = nlohmann::json::array();
  while (std::getline(text, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cells = splitFields(line);
    nlohmann::json row = nlohmann::json::object();
    for (size_t i = 0; i < header.size() && i < cells.size(); ++i) {
      char* end = nullptr;
      double number = std::strtod(cells[i].c_str(), &end);
      bool numeric = !cells[i].empty() && end == cells[i].c_str() + cells[i].size();
      row[header[i]] = numeric ? nlohmann::json(number) : nlohmann::json(cells[i]);
    }
    rows.push_back(row);
  }
  return rows;
}

int runStudy(const StudyCommandOptions& options, const GlobalOptions& global) {
  if (options.name.empty()) return listStudies(options.json);
  const Study& study = findStudy(options.name);
  if (options.output.empty()) throw InputError("study " + options.name + ": -o DIR is required");
  StudyOptions run{options.output, study.defaultWidth, study.defaultHeight};
  if (!options.size.empty()) {
    Size size = parseSize(options.size, "--size");
    run.width = size.width;
    run.height = size.height;
  }
  std::error_code error;
  bool folderExisted = std::filesystem::is_directory(run.output, error);
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
  // Each row the study measures, on a terminal only (its table is printed at the end).
  Progress progress("study " + options.name, 0.0);
  services.progress = [&](const std::string& line) { progress.step(line); };
  std::fprintf(stderr, "study %s at %ux%u: %s\n", options.name.c_str(), run.width, run.height,
               std::string(study.summary).c_str());
  StudyResult result;
  const auto start = std::chrono::steady_clock::now();
  try {
    result = study.run(run, services);
  } catch (...) {
    // A failed study (a bad size, a write that failed) leaves nothing: the
    // folder is removed with what it wrote when this run made it.
    renderer.reset();
    if (!folderExisted) std::filesystem::remove_all(run.output, error);
    throw;
  }
  progress.finish();
  renderer.reset();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  FILE* out = options.json.human();
  std::fprintf(out, "%s", result.report.c_str());
  std::fprintf(out, "wrote into %s:", run.output.c_str());
  for (const std::string& file : result.files) std::fprintf(out, " %s", file.c_str());
  std::fprintf(out, "\n");
  if (options.json.enabled()) {
    nlohmann::json json = {{"study", std::string(study.name)},
                           {"settings", {{"width", run.width}, {"height", run.height}}},
                           {"timings", {{"wall_seconds", seconds}}},
                           {"report", nlohmann::json::array()},
                           {"tables", nlohmann::json::object()},
                           {"outputs", {{"folder", jsonPath(run.output)}, {"files", {}}}}};
    std::stringstream report(result.report);
    for (std::string line; std::getline(report, line);) json["report"].push_back(line);
    for (const std::string& file : result.files) {
      json["outputs"]["files"].push_back(jsonPath(run.output / file));
      if (std::filesystem::path(file).extension() == ".csv")
        json["tables"][file] = csvRows(run.output / file);
    }
    options.json.emit("study", json);
  }
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
  command->add_option(
      "-o,--output", options->output,
      "Folder for the study's images, CSV and chart (created if needed, in a folder that exists)");
  command->add_option("--size", options->size,
                      "Image size WIDTHxHEIGHT (default: the study's own, e.g. 640x360)");
  options->json.add(command);
  return [options, &global] { return runStudy(*options, global); };
}

}  // namespace shadelab
