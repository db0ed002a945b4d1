#include "core/scene/scene_json_textures.h"

#include "core/base/errors.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/texture.h"

namespace shadelab::scene_json {
namespace {

constexpr std::string_view kDiffuse = "diffuse_map";
constexpr std::string_view kNormal = "normal_map";
constexpr std::string_view kHeight = "height_map";

SamplerDesc parseSampler(const Field& field) {
  field.expectObject({"wrap_u", "wrap_v", "filter", "anisotropy"});
  SamplerDesc sampler;
  if (auto f = field.optional("wrap_u")) sampler.wrapU = f->choose("wrap mode", kTextureWrapNames);
  if (auto f = field.optional("wrap_v")) sampler.wrapV = f->choose("wrap mode", kTextureWrapNames);
  if (auto f = field.optional("filter")) sampler.filter = f->choose("filter", kTextureFilterNames);
  if (auto f = field.optional("anisotropy")) {
    sampler.maxAnisotropy = f->number();
    if (!(sampler.maxAnisotropy >= 2.0f && sampler.maxAnisotropy <= 16.0f))
      f->fail("anisotropy " + formatNumber(sampler.maxAnisotropy) + " is out of range",
              "a number from 2 to 16 (the samples along the longer axis)");
    if (sampler.filter != TextureFilter::Anisotropic)
      f->fail("anisotropy without \"filter\": \"aniso\"", "\"filter\": \"aniso\" beside it");
  }
  return sampler;
}

glm::vec2 parseUvScale(const Field& field) {
  if (field.json().is_number()) return glm::vec2(field.positive());
  std::vector<Field> elements = field.elements("a number or [u, v] of repeats > 0");
  if (elements.size() != 2) field.wrongType("a number or [u, v] of repeats > 0");
  return {elements[0].positive(), elements[1].positive()};
}

}  // namespace

const Names& TextureLibrary::fieldNames() {
  static const Names names = {kDiffuse,  kNormal,      kHeight,   "bump_scale",
                              "sampler", "uv_mapping", "uv_scale"};
  return names;
}

void TextureLibrary::parseTextures(const Field& material, const std::string& owner, Material& out) {
  SamplerDesc sampler;
  if (auto f = material.optional("sampler")) sampler = parseSampler(*f);
  out.diffuseMap.sampler = out.normalMap.sampler = out.heightMap.sampler = sampler;
  if (auto f = material.optional(kDiffuse))
    out.diffuseMap.texture = mapTexture(*f, owner, kDiffuse);
  if (auto f = material.optional(kNormal)) out.normalMap.texture = mapTexture(*f, owner, kNormal);
  if (auto f = material.optional(kHeight)) out.heightMap.texture = mapTexture(*f, owner, kHeight);
  if (auto f = material.optional("bump_scale")) out.bumpScale = f->nonNegative();
  if (auto f = material.optional("uv_mapping"))
    out.uvProjection = f->choose("uv mapping", kUvProjectionNames);
  if (auto f = material.optional("uv_scale")) out.uvScale = parseUvScale(*f);
}

int32_t TextureLibrary::mapTexture(const Field& field, const std::string& owner,
                                   std::string_view slot) {
  if (field.json().is_string()) return fileTexture(field, owner, slot);
  if (field.json().is_object()) return proceduralTexture(field, slot);
  field.wrongType("an image file name or {\"procedural\": ...}");
}

int32_t TextureLibrary::fileTexture(const Field& field, const std::string& owner,
                                    std::string_view slot) {
  std::filesystem::path path = field.string();
  if (path.is_relative()) path = baseDir_ / path;
  TextureRole role = slot == kDiffuse ? TextureRole::Color : TextureRole::Data;
  std::string key = path.string() + (role == TextureRole::Color ? " (colour)" : " (data)");
  if (auto found = loaded_.find(key); found != loaded_.end()) return found->second;
  try {
    return add(key, loadTextureFile(path, role, sceneTexels(scene_)));
  } catch (const InputError& error) {
    // A file of the wrong kind says what it should have been (a regular
    // file); one that does not decode, what it should hold.
    std::string problem = std::string(error.what()) + " (" + owner + ")";
    if (problem.find("expected") != std::string::npos) field.fail(problem);
    field.fail(problem, "an image file (PNG, JPEG, HDR, EXR) relative to the scene file");
  }
}

int32_t TextureLibrary::proceduralTexture(const Field& field, std::string_view slot) {
  // A colour texture with alpha, not a height field: diffuse maps only.
  if (slot == kDiffuse && field.has("procedural") && field.at("procedural").json() == "tree") {
    field.expectObject({"procedural", "size"});
    uint32_t size = 128;
    if (auto f = field.optional("size")) size = f->integer(1, 4096, "texels per side");
    std::string key = field.json().dump() + " " + std::string(slot);
    if (auto found = loaded_.find(key); found != loaded_.end()) return found->second;
    return add(key, treeTexture(size, "procedural tree"));
  }
  Names allowed = {"procedural", "size", "repeats"};
  if (slot == kDiffuse) allowed.push_back("colors");
  if (slot == kNormal) allowed.push_back("depth");
  field.expectObject(allowed);
  ProceduralTexture desc;
  desc.pattern =
      field.required("procedural", "a generator name").choose("generator", kHeightPatternNames);
  if (auto f = field.optional("size")) desc.size = f->integer(1, 4096, "texels per side");
  if (auto f = field.optional("repeats")) desc.repeats = f->integer(1, 4096, "cells per side");
  glm::vec3 low{0.0f}, high{1.0f};
  if (auto f = field.optional("colors")) {
    std::vector<Field> colors = f->elements("two colours [low, high]");
    if (colors.size() != 2) f->wrongType("two colours [low, high]");
    low = colors[0].colour();
    high = colors[1].colour();
  }
  float depth = 4.0f;
  if (auto f = field.optional("depth")) depth = f->nonNegative();
  std::string name = std::string("procedural ") + heightPatternName(desc.pattern);
  std::string key = field.json().dump() + " " + std::string(slot);
  if (auto found = loaded_.find(key); found != loaded_.end()) return found->second;
  HeightField height = proceduralHeight(desc);
  if (slot == kDiffuse) return add(key, heightColorTexture(height, low, high, name));
  if (slot == kNormal) return add(key, normalMapTexture(height, depth, name + " (normal map)"));
  return add(key, heightMapTexture(height, name));
}

int32_t TextureLibrary::add(const std::string& key, Texture texture) {
  scene_.textures.push_back(std::move(texture));
  int32_t index = int32_t(scene_.textures.size() - 1);
  loaded_[key] = index;
  return index;
}

}  // namespace shadelab::scene_json
