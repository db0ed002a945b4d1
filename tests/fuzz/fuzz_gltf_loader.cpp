// libFuzzer entry point: any bytes, as a .gltf or .glb, must load or raise
// InputError; anything else (a crash, a sanitizer report, another exception)
// is a bug. Built with clang by the `fuzz` preset (scripts/fuzz.sh), and
// replayed over mutated seeds by every build (replay_main.cpp).
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/base/errors.h"
#include "core/scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    shadelab::parseGltfScene(std::span(data, size), "fuzz-input");
  } catch (const shadelab::InputError&) {
  }
  return 0;
}
