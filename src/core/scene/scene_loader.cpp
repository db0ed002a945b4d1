#include "core/scene/scene_loader.h"

#include <filesystem>

#include "core/base/errors.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/scene_json.h"

namespace shadelab {

Scene loadScene(const std::string& nameOrPath, const TriangleBudget& budget) {
  if (nameOrPath.empty()) return builtinScene("default");
  std::filesystem::path path(nameOrPath);
  std::string ext = path.extension().string();
  bool looksLikeFile = ext == ".json" || ext == ".gltf" || ext == ".glb" ||
                       nameOrPath.find('/') != std::string::npos;
  if (looksLikeFile) {
    if (!std::filesystem::exists(path))
      throw InputError("scene file '" + nameOrPath + "' does not exist");
    if (ext == ".json") return loadSceneJson(path, budget);
    if (ext == ".gltf" || ext == ".glb") return loadGltfScene(path);
    throw InputError("scene file '" + nameOrPath + "': unknown file type " +
                     (ext.empty() ? std::string("(no extension)") : ext) +
                     "; expected .json, .gltf or .glb");
  }
  return builtinScene(nameOrPath);
}

}  // namespace shadelab
