#pragma once
// Internal to the glTF loader (gltf_*.cpp): tinygltf's model to meshes,
// materials and textures, every index and byte range checked first.
#include <tiny_gltf.h>

#include <map>
#include <string>
#include <utility>

#include "core/scene/scene.h"

namespace shadelab::gltf {

// Throws InputError "<source>: <where>: <what>".
[[noreturn]] void fail(const std::string& source, const std::string& where,
                       const std::string& what);
std::string describeMesh(const tinygltf::Model& model, int mesh);  // meshes[2] 'name'

// The triangles of one primitive, indexed, with normals (flat when the file
// has none, as the glTF spec requires), UVs and, when `needTangents`,
// tangents (generated when missing). Points and lines give an empty mesh.
// Vertices are ordered for the vertex cache and fetch (meshoptimizer).
Mesh primitiveMesh(const tinygltf::Model& model, const std::string& source, int mesh, int primitive,
                   bool needTangents);

// glTF materials as Phong materials (formula in README.md), their textures
// appended to the scene once each.
class MaterialTable {
 public:
  MaterialTable(const tinygltf::Model& model, const std::string& source, Scene& scene);
  // -1: the primitive has no material.
  const Material& material(int index);
  bool needsTangents(int index) const;

 private:
  TextureSlot slot(int textureIndex, int texCoord, bool srgb, const std::string& where);
  SamplerDesc sampler(int index, const std::string& where) const;

  const tinygltf::Model& model_;
  std::string source_;
  Scene& scene_;
  std::map<int, Material> materials_;
  std::map<std::pair<int, bool>, int32_t> textures_;  // (image, srgb) -> Scene::textures
};

}  // namespace shadelab::gltf
