// shadelab: one binary, subcommands. main only parses and dispatches; each
// command lives in its own cmd_*.cpp.
#include <malloc.h>

#include <cstdio>
#include <map>

#include "app/commands.h"
#include "core/base/errors.h"

#ifndef SHADELAB_VALIDATION_DEFAULT
#define SHADELAB_VALIDATION_DEFAULT 0
#endif

int main(int argc, char** argv) {
  using namespace shadelab;
  // lavapipe runs in this process and allocates its vertex output per draw.
  // With glibc's defaults each large block is mmapped, page-faulted in and
  // unmapped again every frame; on a 102,400-triangle mesh that made one
  // frame in four take 3x the median (p95 52 ms vs 16 ms, `render dense
  // --frames 150 --mode unlit`). Keeping freed memory in the heap removes
  // those spikes (p95 20 ms) and lowers the median by ~5%.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  CLI::App app{"shadelab: classic real-time rendering on Vulkan, measured"};
  app.require_subcommand(1);
  app.fallthrough();  // global options may follow the subcommand name
  GlobalOptions global;
  global.validate = SHADELAB_VALIDATION_DEFAULT;
  app.add_flag("--validate,!--no-validate", global.validate,
               "Enable the Vulkan validation layer; any message makes the exit code non-zero");
  app.add_option("--device", global.device, "Use the Vulkan 1.3 device whose name contains NAME");

  std::map<std::string, CommandRunner> commands = {
      {"render", addRenderCommand(app, global)}, {"compare", addCompareCommand(app, global)},
      {"bench", addBenchCommand(app, global)},   {"info", addInfoCommand(app, global)},
      {"trace", addTraceCommand(app, global)},   {"scenes", addScenesCommand(app, global)},
      {"study", addStudyCommand(app, global)},   {"view", addViewCommand(app, global)},
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    app.exit(error);
    return 2;  // usage error
  }
  try {
    return commands.at(app.get_subcommands().front()->get_name())();
  } catch (const InputError& error) {
    std::fprintf(stderr, "shadelab: error: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "shadelab: internal error: %s\n", error.what());
    return 1;
  }
}
