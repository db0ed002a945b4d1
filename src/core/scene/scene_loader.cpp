#include "core/scene/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/base/errors.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/scene_json.h"

namespace shadelab {

Scene loadScene(const std::string& nameOrPath, const TriangleBudget& budget) {
  if (nameOrPath.empty()) return builtinScene("default");
  std::filesystem::path path(nameOrPath);
  // Extensions in any case (SCENE.JSON, model.GLB); a name that is no
  // built-in but names a file is that file, whatever its extension says.
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  std::vector<std::string> builtins = builtinSceneNames();
  std::error_code error;
  bool looksLikeFile = ext == ".json" || ext == ".gltf" || ext == ".glb" ||
                       nameOrPath.find('/') != std::string::npos ||
                       (std::find(builtins.begin(), builtins.end(), nameOrPath) == builtins.end() &&
                        std::filesystem::exists(path, error));
  if (looksLikeFile) {
    if (!std::filesystem::exists(path, error))
      throw InputError("scene file '" + nameOrPath + "' does not exist");
    if (std::filesystem::is_directory(path, error))
      throw InputError("scene file '" + nameOrPath +
                       "' is a directory, expected a .json, .gltf or .glb file");
    if (ext == ".json") return loadSceneJson(path, budget);
    if (ext == ".gltf" || ext == ".glb") return loadGltfScene(path);
    throw InputError("scene file '" + nameOrPath + "': unknown file type " +
                     (ext.empty() ? std::string("(no extension)") : ext) +
                     "; expected .json, .gltf or .glb");
  }
  return builtinScene(nameOrPath);
}

}  // namespace shadelab
