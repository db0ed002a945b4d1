#pragma once
// The real-world inputs of ../shared/assets (BRIEF: CI clones the repository
// with shared/ beside it). SHADELAB_SHARED_ASSETS in the environment
// overrides the compile-time path; tests GTEST_SKIP when it is absent.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab::test {

inline std::filesystem::path sharedAssetsDir() {
  if (const char* overridden = std::getenv("SHADELAB_SHARED_ASSETS")) return overridden;
  return SHADELAB_SHARED_ASSETS;
}

// The .gltf and .glb files of shared/assets/models, sorted; empty when absent.
inline std::vector<std::filesystem::path> sharedModels() {
  std::vector<std::filesystem::path> models;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(sharedAssetsDir() / "models", error))
    if (entry.path().extension() == ".gltf" || entry.path().extension() == ".glb")
      models.push_back(entry.path());
  std::sort(models.begin(), models.end());
  return models;
}

}  // namespace shadelab::test
