// shadelab scenes: the built-in scenes, one line each, or one scene's JSON on
// stdout to copy and edit (`scenes --print default > my.json`). No Vulkan device.
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "app/commands.h"
#include "core/scene/scene.h"

namespace shadelab {
namespace {

int listScenes() {
  std::vector<std::string> names = builtinSceneNames();
  size_t width = 0;
  for (const std::string& name : names) width = std::max(width, name.size());
  for (const std::string& name : names)
    std::printf("%-*s  %s\n", int(width), name.c_str(), builtinSceneDescription(name).c_str());
  // For a reader at a terminal; a pipe gets just the list.
  if (isatty(STDOUT_FILENO))
    std::printf(
        "\nCopy one to edit: shadelab scenes --print NAME > my.json; "
        "then shadelab render my.json -o my.png\n");
  return 0;
}

int printScene(const std::string& name) {
  std::string_view json = builtinSceneJson(name);  // InputError for an unknown name
  if (std::fwrite(json.data(), 1, json.size(), stdout) != json.size() || std::fflush(stdout) != 0) {
    std::fprintf(stderr, "shadelab: error: cannot write the scene to stdout\n");
    return 1;
  }
  return 0;
}

}  // namespace

CommandRunner addScenesCommand(CLI::App& app, const GlobalOptions&) {
  auto name = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "scenes", "List the built-in scenes, or print one's JSON file to copy and edit");
  CLI::Option* print = command->add_option(
      "--print", *name, "Write the built-in scene NAME's JSON to stdout (as in assets/scenes/)");
  print->option_text("NAME");
  return [name, print] { return print->count() > 0 ? printScene(*name) : listScenes(); };
}

}  // namespace shadelab
