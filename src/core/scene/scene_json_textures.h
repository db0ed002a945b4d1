#pragma once
// The texture fields of a JSON material (documented at the top of
// scene_json.cpp): maps from files or procedural generators, the sampler,
// the bump scale and the UV mapping. Private to scene_json*.cpp.
#include <filesystem>
#include <map>
#include <string>

#include "core/scene/scene.h"
#include "core/scene/scene_json_fields.h"

namespace shadelab::scene_json {

// Loads each texture once per scene (the same file as colour and as data is
// two textures: sRGB and linear) and appends it to Scene::textures.
class TextureLibrary {
 public:
  TextureLibrary(Scene& scene, std::filesystem::path baseDir)
      : scene_(scene), baseDir_(std::move(baseDir)) {}

  // The material keys parseTextures reads.
  static const Names& fieldNames();
  // `owner` names the material in messages ("material 'brick'").
  void parseTextures(const Field& material, const std::string& owner, Material& out);

 private:
  int32_t mapTexture(const Field& field, const std::string& owner, std::string_view slot);
  int32_t fileTexture(const Field& field, const std::string& owner, std::string_view slot);
  int32_t proceduralTexture(const Field& field, std::string_view slot);
  int32_t add(const std::string& key, Texture texture);

  Scene& scene_;
  std::filesystem::path baseDir_;
  std::map<std::string, int32_t> loaded_;  // file or generator + slot -> Scene::textures index
};

}  // namespace shadelab::scene_json
