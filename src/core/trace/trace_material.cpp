#include "core/trace/trace_material.h"

#include <algorithm>
#include <cmath>

namespace shadelab {
namespace {

// Where a texture is sampled, as shaders/texturing.glsl's textureCoordinate.
glm::vec2 textureCoordinate(glm::vec2 uv, glm::vec2 scale) {
  return {uv.x * scale.x, 1.0f - uv.y * scale.y};
}

struct Lookup {
  glm::vec2 st;
  glm::vec2 stPerAlong, stPerAcross;  // st per footprint axis (already times its length)
};

float levelOfDetail(const Lookup& lookup, const TraceTexture& texture) {
  const glm::vec2 size(texture.size());
  const float longest =
      std::max(glm::length(lookup.stPerAlong * size), glm::length(lookup.stPerAcross * size));
  return longest > 0.0f ? std::log2(longest) : 0.0f;
}

// KHR_texture_transform on a lookup: st' = T(offset) R(rotation) S(scale) st
// (shaders/uv_transform.glsl's matrices), and its rates through the linear part.
Lookup transformed(const Lookup& lookup, const UvTransform& transform) {
  if (transform.identity()) return lookup;
  const float c = std::cos(transform.rotation), s = std::sin(transform.rotation);
  auto linear = [&](glm::vec2 v) {
    const glm::vec2 scaled = v * transform.scale;
    return glm::vec2(c * scaled.x + s * scaled.y, c * scaled.y - s * scaled.x);
  };
  return {linear(lookup.st) + transform.offset, linear(lookup.stPerAlong),
          linear(lookup.stPerAcross)};
}

glm::vec4 sampleAt(const TraceTexture& texture, const TextureSlot& slot, const Lookup& lookup,
                   glm::vec2 offset = glm::vec2(0.0f)) {
  return texture.sample(lookup.st + offset, levelOfDetail(lookup, texture), slot.sampler);
}

// shaders/bump.glsl heightMapNormal: central differences one level-0 texel apart.
glm::vec3 heightMapNormal(const TraceTexture& texture, const TextureSlot& slot,
                          const Lookup& lookup, float scale) {
  const glm::vec2 texel = 1.0f / glm::vec2(texture.size());
  const float dhdu = 0.5f * (sampleAt(texture, slot, lookup, {texel.x, 0.0f}).r -
                             sampleAt(texture, slot, lookup, {-texel.x, 0.0f}).r);
  const float dhdv = 0.5f * (sampleAt(texture, slot, lookup, {0.0f, -texel.y}).r -
                             sampleAt(texture, slot, lookup, {0.0f, texel.y}).r);
  return {-scale * dhdu, -scale * dhdv, 1.0f};
}

// The tangent frame the mesh's tangents approximate: T along dp/du, B's
// sign from dp/dv (core/scene/mesh.cpp computeTangents), here from the inverse of
// the uv Jacobian. False where the uv does not vary (no frame).
bool tangentFrame(const UvFrame& frame, glm::vec3 normal, glm::vec3& tangent,
                  glm::vec3& bitangent) {
  const glm::mat2 jacobian(frame.uvPerAlong, frame.uvPerAcross);
  const float determinant = glm::determinant(jacobian);
  if (!(std::abs(determinant) > 1e-20f) || !std::isfinite(determinant)) return false;
  const glm::mat2 inverse = glm::inverse(jacobian);
  const glm::vec3 dpdu = inverse[0][0] * frame.along + inverse[0][1] * frame.across;
  const glm::vec3 dpdv = inverse[1][0] * frame.along + inverse[1][1] * frame.across;
  const glm::vec3 projected = dpdu - normal * glm::dot(normal, dpdu);
  if (!(glm::length(projected) > 0.0f)) return false;
  tangent = glm::normalize(projected);
  const float handedness = glm::dot(glm::cross(normal, tangent), dpdv) < 0.0f ? -1.0f : 1.0f;
  bitangent = handedness * glm::cross(normal, tangent);
  return true;
}

}  // namespace

void tangentPlaneAxes(glm::vec3 normal, glm::vec3 incident, glm::vec3& along, glm::vec3& across) {
  glm::vec3 projected = incident - normal * glm::dot(normal, incident);
  if (!(glm::length(projected) > 1e-6f)) {  // head-on: any direction in the plane
    projected = std::abs(normal.x) < 0.9f ? glm::cross(normal, glm::vec3(1, 0, 0))
                                          : glm::cross(normal, glm::vec3(0, 1, 0));
  }
  along = glm::normalize(projected);
  across = glm::cross(normal, along);
}

Material texturedMaterial(const Material& material, const std::vector<TraceTexture>& textures,
                          const UvFrame& frame, float footprint, float cosine, glm::vec3& normal) {
  Material result = material;
  const glm::vec2 scale = material.uvScale * glm::vec2(1.0f, -1.0f);  // t = 1 - v sy
  const float alongLength = footprint / std::max(cosine, 1e-4f);
  const Lookup untransformed{textureCoordinate(frame.uv, material.uvScale),
                             frame.uvPerAlong * scale * alongLength,
                             frame.uvPerAcross * scale * footprint};
  // The normal map's transform serves the height map too, as in the shaders.
  const Lookup lookup = transformed(untransformed, material.normalMap.transform);
  if (material.diffuseMap.present()) {
    const glm::vec4 texel =
        sampleAt(textures[size_t(material.diffuseMap.texture)], material.diffuseMap,
                 transformed(untransformed, material.diffuseMap.transform));
    result.ka *= glm::vec3(texel);
    result.kd *= glm::vec3(texel);
    // Coverage (glTF BLEND, blended billboards): the texel's alpha times the
    // material's opacity.
    if (material.alphaCoverage)
      result.transparency = 1.0f - (1.0f - material.transparency) * glm::clamp(texel.a, 0.0f, 1.0f);
  }
  const bool normalMapped = material.normalMap.present(),
             heightMapped = material.heightMap.present();
  glm::vec3 tangent, bitangent;
  if ((!normalMapped && !heightMapped) || !tangentFrame(frame, normal, tangent, bitangent))
    return result;
  glm::vec3 n{0.0f, 0.0f, 1.0f};
  if (normalMapped) {
    const glm::vec3 mapped = glm::vec3(sampleAt(textures[size_t(material.normalMap.texture)],
                                                material.normalMap, lookup)) *
                                 2.0f -
                             1.0f;
    n = {glm::vec2(mapped) * material.bumpScale, mapped.z};
  }
  if (heightMapped) {
    const glm::vec3 h = heightMapNormal(textures[size_t(material.heightMap.texture)],
                                        material.heightMap, lookup, material.bumpScale);
    n = {glm::vec2(n) + glm::vec2(h), n.z * h.z};
  }
  const glm::vec3 bumped = tangent * n.x + bitangent * n.y + normal * n.z;
  if (glm::length(bumped) > 0.0f) normal = glm::normalize(bumped);
  return result;
}

float coverage(const Material& material, const std::vector<TraceTexture>& textures, glm::vec2 uv) {
  const float opacity = 1.0f - material.transparency;
  if (!material.diffuseMap.present()) return opacity;
  const Lookup lookup =
      transformed({textureCoordinate(uv, material.uvScale), {}, {}}, material.diffuseMap.transform);
  const TraceTexture& texture = textures[size_t(material.diffuseMap.texture)];
  return opacity *
         glm::clamp(texture.sample(lookup.st, 0.0f, material.diffuseMap.sampler).a, 0.0f, 1.0f);
}

bool cutAway(const Material& material, const std::vector<TraceTexture>& textures, glm::vec2 uv) {
  if (!(material.alphaCutoff > 0.0f)) return false;
  // alpha x texel < cutoff, as the shaders compare texel < cutoff / alpha.
  const float threshold = material.alpha > 0.0f ? material.alphaCutoff / material.alpha : 2.0f;
  if (!material.diffuseMap.present()) return threshold > 1.0f;
  const Lookup lookup =
      transformed({textureCoordinate(uv, material.uvScale), {}, {}}, material.diffuseMap.transform);
  const TraceTexture& texture = textures[size_t(material.diffuseMap.texture)];
  return texture.sample(lookup.st, 0.0f, material.diffuseMap.sampler).a < threshold;
}

}  // namespace shadelab
