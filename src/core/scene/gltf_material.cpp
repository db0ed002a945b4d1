// glTF metallic-roughness materials onto the Phong material (README.md,
// "glTF materials"), and their textures and samplers onto Scene::textures
// and SamplerDesc.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/scene/gltf_detail.h"
#include "core/scene/texture.h"

namespace shadelab::gltf {
namespace {

glm::vec3 vec3Of(const std::vector<double>& values, glm::vec3 fallback) {
  if (values.size() < 3) return fallback;
  return glm::vec3(float(values[0]), float(values[1]), float(values[2]));
}

float clamp01(double value) {
  return std::clamp(float(value), 0.0f, 1.0f);
}

TextureWrap wrapOf(int mode) {
  switch (mode) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
      return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
      return TextureWrap::MirroredRepeat;
    default:
      return TextureWrap::Repeat;
  }
}

// The minification filter decides (it is the one with mip levels); without
// one, the magnification filter; without either, trilinear.
TextureFilter filterOf(int minFilter, int magFilter) {
  switch (minFilter) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      return TextureFilter::Nearest;
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      return TextureFilter::Bilinear;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
      return TextureFilter::Trilinear;
    default:
      break;
  }
  return magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? TextureFilter::Nearest
                                                      : TextureFilter::Trilinear;
}

// 8-bit RGBA from what tinygltf's stb loader decoded (RGBA, 8 or 16 bits).
std::vector<uint8_t> rgba8Of(const tinygltf::Image& image) {
  size_t texels = size_t(image.width) * size_t(image.height);
  if (image.bits == 8) return image.image;
  std::vector<uint8_t> rgba(texels * 4);
  for (size_t i = 0; i < rgba.size(); ++i) {
    uint16_t value = uint16_t(image.image[2 * i] | (image.image[2 * i + 1] << 8));
    rgba[i] = uint8_t((uint32_t(value) * 255 + 32767) / 65535);
  }
  return rgba;
}

// KHR_texture_transform's numbers: each finite, or the field is refused.
float finiteNumber(const tinygltf::Value& value, const std::string& source,
                   const std::string& field) {
  if (!value.IsNumber() || !std::isfinite(value.GetNumberAsDouble()) ||
      !std::isfinite(float(value.GetNumberAsDouble())))
    fail(source, field, "expected a finite number");
  return float(value.GetNumberAsDouble());
}

glm::vec2 finitePair(const tinygltf::Value& value, const std::string& source,
                     const std::string& field) {
  if (!value.IsArray() || value.ArrayLen() != 2)
    fail(source, field, "expected an array of two finite numbers");
  return glm::vec2(finiteNumber(value.Get(0), source, field + "[0]"),
                   finiteNumber(value.Get(1), source, field + "[1]"));
}

}  // namespace

void checkAlphaCutoffs(std::string_view json, const std::string& source) {
  if (json.find("alphaCutoff") == std::string_view::npos) return;  // nothing to check
  // Keep only "materials" of the top level: buffers may be megabytes of base64.
  nlohmann::json::parser_callback_t onlyMaterials = [](int depth,
                                                       nlohmann::json::parse_event_t event,
                                                       nlohmann::json& parsed) {
    return !(depth == 1 && event == nlohmann::json::parse_event_t::key && parsed != "materials");
  };
  nlohmann::json root = nlohmann::json::parse(json, onlyMaterials, false);
  if (!root.is_object() || !root.contains("materials") || !root["materials"].is_array()) return;
  const nlohmann::json& materials = root["materials"];
  for (size_t i = 0; i < materials.size(); ++i) {
    if (!materials[i].is_object() || !materials[i].contains("alphaCutoff")) continue;
    const nlohmann::json& cutoff = materials[i]["alphaCutoff"];
    std::string field = "materials[" + std::to_string(i) + "].alphaCutoff";
    if (!cutoff.is_number())
      fail(source, field, "expected a number >= 0, got " + cutoff.dump().substr(0, 40));
    if (!(cutoff.get<double>() >= 0.0) || !std::isfinite(cutoff.get<double>()))
      fail(source, field, "expected a number >= 0, got " + cutoff.dump());
  }
}

MaterialTable::MaterialTable(const tinygltf::Model& model, const std::string& source, Scene& scene)
    : model_(model), source_(source), scene_(scene) {}

bool MaterialTable::needsTangents(int index) const {
  return index >= 0 && size_t(index) < model_.materials.size() &&
         model_.materials[size_t(index)].normalTexture.index >= 0;
}

MaterialTable::TextureReference MaterialTable::reference(int index, int texCoord,
                                                         const tinygltf::ExtensionMap& extensions,
                                                         const std::string& where) const {
  TextureReference reference{index, texCoord, {}};
  auto found = extensions.find("KHR_texture_transform");
  if (index < 0 || found == extensions.end()) return reference;
  const tinygltf::Value& transform = found->second;
  std::string field = where + ".extensions.KHR_texture_transform";
  if (!transform.IsObject()) fail(source_, field, "expected an object");
  if (transform.Has("offset"))
    reference.transform.offset = finitePair(transform.Get("offset"), source_, field + ".offset");
  if (transform.Has("rotation"))
    reference.transform.rotation =
        finiteNumber(transform.Get("rotation"), source_, field + ".rotation");
  if (transform.Has("scale"))
    reference.transform.scale = finitePair(transform.Get("scale"), source_, field + ".scale");
  if (transform.Has("texCoord")) {
    const tinygltf::Value& set = transform.Get("texCoord");
    double value = set.IsNumber() ? set.GetNumberAsDouble() : -1.0;
    if (!(value >= 0.0 && value <= 255.0 && value == std::floor(value)))
      fail(source_, field + ".texCoord", "expected an integer from 0 to 255");
    reference.set = int(value);  // overrides the textureInfo's texCoord
  }
  return reference;
}

int MaterialTable::texCoordSet(int index) const {
  if (index < 0 || size_t(index) >= model_.materials.size()) return 0;
  const tinygltf::Material& source = model_.materials[size_t(index)];
  std::string where = "materials[" + std::to_string(index) + "]";
  const tinygltf::TextureInfo& base = source.pbrMetallicRoughness.baseColorTexture;
  if (base.index >= 0)
    return reference(base.index, base.texCoord, base.extensions,
                     where + ".pbrMetallicRoughness.baseColorTexture")
        .set;
  const tinygltf::NormalTextureInfo& normal = source.normalTexture;
  return reference(normal.index, normal.texCoord, normal.extensions, where + ".normalTexture").set;
}

const Material& MaterialTable::material(int index) {
  auto found = materials_.find(index);
  if (found != materials_.end()) return found->second;
  std::string where = "materials[" + std::to_string(index) + "]";
  if (index >= int(model_.materials.size())) fail(source_, where, "no such material");
  // No material: white plastic (baseColor 1, metallic 0, roughness 0.5).
  tinygltf::Material gltfMaterial;
  gltfMaterial.pbrMetallicRoughness.metallicFactor = 0.0;
  gltfMaterial.pbrMetallicRoughness.roughnessFactor = 0.5;
  const tinygltf::Material& source = index >= 0 ? model_.materials[size_t(index)] : gltfMaterial;
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  if (source.alphaMode != "OPAQUE" && source.alphaMode != "MASK" && source.alphaMode != "BLEND")
    fail(source_, where + ".alphaMode",
         "\"" + source.alphaMode.substr(0, 32) + "\"; expected OPAQUE, MASK or BLEND");

  glm::vec3 base = glm::clamp(vec3Of(pbr.baseColorFactor, glm::vec3(1.0f)), 0.0f, 1.0f);
  float alpha = pbr.baseColorFactor.size() >= 4 ? clamp01(pbr.baseColorFactor[3]) : 1.0f;
  float metallic = clamp01(pbr.metallicFactor);
  float roughness = clamp01(pbr.roughnessFactor);
  Material material;
  // Metals have no diffuse term and tint their highlight; dielectrics reflect
  // about 4% at normal incidence (the glTF spec's F0).
  material.kd = base * (1.0f - metallic);
  material.ka = material.kd;
  material.ks = glm::mix(glm::vec3(0.04f), base, metallic);
  // Phong exponent of the same lobe width as the GGX alpha = roughness^2
  // (n = 2 / alpha^2 - 2, Walter et al. 2007), clamped to a drawable range.
  float a = std::max(roughness * roughness, 1e-3f);
  material.shininess = std::clamp(2.0f / (a * a) - 2.0f, 1.0f, 2048.0f);
  // 0..1 as the spec bounds it (like baseColorFactor); the extension's strength scales past 1.
  material.emissive = glm::clamp(vec3Of(source.emissiveFactor, glm::vec3(0.0f)), 0.0f, 1.0f);
  auto strength = source.extensions.find("KHR_materials_emissive_strength");
  if (strength != source.extensions.end() && strength->second.Has("emissiveStrength")) {
    const std::string field =
        where + ".extensions.KHR_materials_emissive_strength.emissiveStrength";
    float factor = finiteNumber(strength->second.Get("emissiveStrength"), source_, field);
    // At most 1e6, as lights' intensities and environments are bounded.
    if (!(factor >= 0.0f && factor <= 1e6f))
      fail(source_, field, numberText(factor) + "; expected a number from 0 to 1000000");
    material.emissive *= factor;
  }
  // BLEND: covering the factor's alpha times the texel's (the base colour
  // texture's alpha: TEXTURE_ALPHA, trace_material.cpp). MASK: cut out where the factor's alpha
  // times the texel's is below alphaCutoff (checkAlphaCutoffs refused a negative or non-numeric
  // one).
  if (source.alphaMode == "BLEND") {
    material.transparency = 1.0f - alpha;
    material.alphaCoverage = true;
  }
  if (source.alphaMode == "MASK") {
    material.alphaCutoff = float(source.alphaCutoff);
    material.alpha = alpha;
  }
  material.doubleSided = source.doubleSided;
  if (index >= 0) {
    TextureReference base = reference(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                      pbr.baseColorTexture.extensions,
                                      where + ".pbrMetallicRoughness.baseColorTexture");
    TextureReference normal = reference(source.normalTexture.index, source.normalTexture.texCoord,
                                        source.normalTexture.extensions, where + ".normalTexture");
    // The vertices carry one uv set (texCoordSet): a texture on another is not applied.
    int set = texCoordSet(index);
    if (base.set == set) material.diffuseMap = slot(base, true, where);
    if (normal.set == set) material.normalMap = slot(normal, false, where);
    if (material.normalMap.present()) {
      if (!std::isfinite(float(source.normalTexture.scale)))
        fail(source_, where + ".normalTexture.scale",
             numberText(source.normalTexture.scale) + "; expected a finite number");
      material.bumpScale = float(source.normalTexture.scale);
    }
  }
  return materials_[index] = material;
}

TextureSlot MaterialTable::slot(const TextureReference& reference, bool srgb,
                                const std::string& where) {
  TextureSlot slot;
  int textureIndex = reference.index;
  if (textureIndex < 0) return slot;
  slot.transform = reference.transform;
  std::string textureWhere = where + ": textures[" + std::to_string(textureIndex) + "]";
  if (size_t(textureIndex) >= model_.textures.size())
    fail(source_, textureWhere,
         "no such texture (the file has " + std::to_string(model_.textures.size()) + ")");
  const tinygltf::Texture& texture = model_.textures[size_t(textureIndex)];
  if (texture.source < 0 || size_t(texture.source) >= model_.images.size())
    fail(source_, textureWhere,
         "refers to image " + std::to_string(texture.source) + ", which does not exist");
  slot.sampler = sampler(texture.sampler, textureWhere);
  auto key = std::make_pair(texture.source, srgb);
  auto found = textures_.find(key);
  if (found != textures_.end()) {
    slot.texture = found->second;
    return slot;
  }
  const tinygltf::Image& image = model_.images[size_t(texture.source)];
  std::string imageName =
      "images[" + std::to_string(texture.source) + "]" +
      (image.uri.empty() || image.uri.starts_with("data:") ? std::string()
                                                           : " '" + image.uri + "'");
  checkTextureSize(source_ + ": " + imageName, image.width, image.height);
  size_t texels = size_t(std::max(image.width, 0)) * size_t(std::max(image.height, 0));
  if (image.image.empty() || texels == 0 || image.component != 4 ||
      (image.bits != 8 && image.bits != 16) ||
      image.image.size() != texels * 4 * size_t(image.bits / 8))
    fail(source_, imageName, "could not be loaded or decoded (missing file or unsupported format)");
  Texture loaded;
  loaded.name = source_ + " " + imageName;
  loaded.width = uint32_t(image.width);
  loaded.height = uint32_t(image.height);
  loaded.rgba8 = rgba8Of(image);
  loaded.srgb = srgb;
  scene_.textures.push_back(std::move(loaded));
  slot.texture = int32_t(scene_.textures.size() - 1);
  textures_[key] = slot.texture;
  return slot;
}

SamplerDesc MaterialTable::sampler(int index, const std::string& where) const {
  SamplerDesc desc;  // no sampler: repeat, auto filtering (trilinear)
  if (index < 0) return desc;
  if (size_t(index) >= model_.samplers.size())
    fail(source_, where, "refers to sampler " + std::to_string(index) + ", which does not exist");
  const tinygltf::Sampler& sampler = model_.samplers[size_t(index)];
  // The spec's enums only: another number is a broken file, not a default.
  const std::string samplerWhere = "samplers[" + std::to_string(index) + "]";
  auto checkEnum = [&](int value, const char* field, std::initializer_list<int> allowed,
                       const char* expected) {
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
      fail(source_, samplerWhere + "." + field,
           std::to_string(value) + "; expected " + expected + " (" + where + ")");
  };
  const char* wraps = "33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT) or 10497 (REPEAT)";
  checkEnum(sampler.wrapS, "wrapS", {33071, 33648, 10497}, wraps);
  checkEnum(sampler.wrapT, "wrapT", {33071, 33648, 10497}, wraps);
  checkEnum(sampler.magFilter, "magFilter", {-1, 9728, 9729}, "9728 (NEAREST) or 9729 (LINEAR)");
  checkEnum(sampler.minFilter, "minFilter", {-1, 9728, 9729, 9984, 9985, 9986, 9987},
            "9728 (NEAREST), 9729 (LINEAR) or 9984-9987 (the MIPMAP ones)");
  desc.wrapU = wrapOf(sampler.wrapS);
  desc.wrapV = wrapOf(sampler.wrapT);
  desc.filter = filterOf(sampler.minFilter, sampler.magFilter);
  return desc;
}

}  // namespace shadelab::gltf
