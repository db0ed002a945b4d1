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
// A number of the file as a message shows it: 0.5, 1e+300.
std::string numberText(double value);

// tinygltf leaves alphaCutoff at 0.5 when it is not a number: every
// materials[i].alphaCutoff in the file's JSON must be a number >= 0
// (InputError naming the field otherwise).
void checkAlphaCutoffs(std::string_view json, const std::string& source);

// The triangles of one primitive, indexed, with normals (flat when the file
// has none, as the glTF spec requires), UVs and, when `needTangents`,
// tangents (generated when missing). Points and lines give an empty mesh.
// Vertices are ordered for the vertex cache and fetch (meshoptimizer).
// `texCoordSet`: which TEXCOORD_n becomes the vertices' uv.
Mesh primitiveMesh(const tinygltf::Model& model, const std::string& source, int mesh, int primitive,
                   bool needTangents, int texCoordSet = 0);

// glTF materials as Phong materials (formula in README.md), their textures
// appended to the scene once each.
class MaterialTable {
 public:
  MaterialTable(const tinygltf::Model& model, const std::string& source, Scene& scene);
  // -1: the primitive has no material.
  const Material& material(int index);
  bool needsTangents(int index) const;
  // The TEXCOORD set the material's textures read (vertices carry one uv):
  // the base colour texture's, else the normal texture's, after
  // KHR_texture_transform's texCoord override; 0 without textures.
  int texCoordSet(int index) const;

 private:
  // A material's texture reference with its KHR_texture_transform (checked:
  // finite numbers, a texCoord >= 0; InputError naming the field otherwise).
  struct TextureReference {
    int index = -1;  // into model.textures; -1: none
    int set = 0;     // TEXCOORD_n it reads
    UvTransform transform;
  };
  TextureReference reference(int index, int texCoord, const tinygltf::ExtensionMap& extensions,
                             const std::string& where) const;
  TextureSlot slot(const TextureReference& reference, bool srgb, const std::string& where);
  SamplerDesc sampler(int index, const std::string& where) const;

  const tinygltf::Model& model_;
  std::string source_;
  Scene& scene_;
  std::map<int, Material> materials_;
  std::map<std::pair<int, bool>, int32_t> textures_;  // (image, srgb) -> Scene::textures
};

}  // namespace shadelab::gltf
