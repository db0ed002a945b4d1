// shadelab: one binary, subcommands. main only parses and dispatches; each
// command lives in its own cmd_*.cpp.
#include <malloc.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>

#include "app/commands.h"
#include "core/base/errors.h"

#ifndef SHADELAB_VALIDATION_DEFAULT
#define SHADELAB_VALIDATION_DEFAULT 0
#endif

int main(int argc, char** argv) {
  using namespace shadelab;
  // llvmpipe allocates its binned scene anew every frame. glibc grows the
  // heap by exactly what is asked and gives the top back when it is freed,
  // so a large frame paid for fresh, zeroed pages each time, in some runs
  // and not others: lod-10000.json --lod auto --impostors off ran at ~48 or
  // ~97 ms a frame from one run to the next. 64 MiB of slack kept at the
  // top of the heap makes every run the fast one; peak RSS is unchanged
  // (docs/PERFORMANCE.md, "Seventeenth session").
  mallopt(M_TOP_PAD, 64 << 20);
  CLI::App app{"shadelab: classic real-time rendering on Vulkan, measured"};
  app.require_subcommand(1);
  app.fallthrough();  // global options may follow the subcommand name
  GlobalOptions global;
  global.validate = SHADELAB_VALIDATION_DEFAULT;
  app.add_flag("--validate,!--no-validate", global.validate,
               "Enable the Vulkan validation layer; any message makes the exit code non-zero");
  app.add_option("--device", global.device, "Use the Vulkan 1.3 device whose name contains NAME");
  app.set_version_flag("--version", std::string("shadelab ") + SHADELAB_VERSION);
  app.add_option("--max-triangles", global.maxTriangles,
                 "Refuse a request estimated to draw more triangles than this (counted before "
                 "anything is built)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);

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
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::ConversionError& error) {
    // CLI11 says "Could not convert: --turntable = 2.5"; say what the option takes.
    std::string what = error.what();
    const std::string prefix = "Could not convert: ";
    size_t equals = what.find(" = ");
    if (!what.starts_with(prefix) || equals == std::string::npos) {
      std::fprintf(stderr, "shadelab: error: %s (see --help)\n", what.c_str());
      return 2;
    }
    std::string name = what.substr(prefix.size(), equals - prefix.size());
    std::string value = what.substr(equals + 3);
    std::string kind = "a value of its type";
    for (const CLI::App* command : app.get_subcommands())
      if (const CLI::Option* option = command->get_option_no_throw(name)) {
        std::string type = option->get_type_name();
        kind = type == "INT" || type == "UINT" ? "an integer" : type == "FLOAT" ? "a number" : type;
      }
    std::fprintf(stderr, "shadelab: error: %s '%s': expected %s (see --help)\n", name.c_str(),
                 value.c_str(), kind.c_str());
    return 2;  // usage error
  } catch (const CLI::ParseError& error) {
    // CLI11's words ("--frames: Value 0 not in range 1 to 100000"), in the
    // form every other error takes.
    std::fprintf(stderr, "shadelab: error: %s (see --help)\n", error.what());
    return 2;  // usage error
  }
  int code = 1;
  try {
    code = commands.at(app.get_subcommands().front()->get_name())();
  } catch (const InputError& error) {
    std::fprintf(stderr, "shadelab: error: %s\n", error.what());
    code = 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "shadelab: internal error: %s\n", error.what());
    code = 1;
  }
  // What went to standard output (scenes --print, --json) is only written
  // once flushed: a full disk there is a failure, not a success.
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "shadelab: error: cannot write to standard output (%s)\n",
                 std::strerror(errno));
    return code == 0 ? 1 : code;
  }
  return code;
}
