#pragma once
// Subcommands of the shadelab binary. Each registers its options on the CLI11
// app; its callback runs the command and returns the process exit code.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace shadelab {

struct GlobalOptions {
  bool validate = false;
  std::string device;
};

using CommandRunner = std::function<int()>;

CommandRunner addRenderCommand(CLI::App& app, const GlobalOptions& global);
CommandRunner addCompareCommand(CLI::App& app, const GlobalOptions& global);
CommandRunner addBenchCommand(CLI::App& app, const GlobalOptions& global);
CommandRunner addInfoCommand(CLI::App& app, const GlobalOptions& global);
CommandRunner addStudyCommand(CLI::App& app, const GlobalOptions& global);
CommandRunner addScenesCommand(CLI::App& app, const GlobalOptions& global);
CommandRunner addTraceCommand(CLI::App& app, const GlobalOptions& global);
CommandRunner addViewCommand(CLI::App& app, const GlobalOptions& global);

}  // namespace shadelab
