// libFuzzer entry point for scene files: any bytes, parsed as a scene JSON
// file, must load or raise InputError; anything else (a crash, a sanitizer
// report, another exception, a hang) is a bug. The file is taken to sit in
// assets/scenes, so the seeds' textures, panoramas and glTF files resolve
// and their loaders run too. A small triangle budget keeps an input fast:
// the budget check is part of what is under test. Built with clang by the
// `fuzz` preset (scripts/fuzz.sh), replayed over mutated seeds by every
// build (replay_main.cpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/base/errors.h"
#include "core/scene/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string source = std::string(SHADELAB_FUZZ_SCENE_DIR) + "/fuzz-input.json";
  const shadelab::TriangleBudget budget{.maxTriangles = 200'000, .option = "--max-triangles"};
  try {
    shadelab::parseSceneJson(std::string_view(reinterpret_cast<const char*>(data), size), source,
                             budget);
  } catch (const shadelab::InputError&) {
  }
  return 0;
}
