#include "core/vulkan/gpu_scene.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <tuple>

#include "core/scene/frustum.h"
#include "core/scene/lighting.h"
#include "core/scene/lod.h"
#include "core/scene/shape.h"
#include "core/scene/transform.h"
#include "core/scene/uv_mapping.h"

namespace shadelab {

// The structs in shaders/interface.h must match std140/std430 exactly.
// An array's stride is 16-byte aligned in std140: GpuLight's 48 bytes are.
static_assert(sizeof(gpu::GpuLight) == 48);
static_assert(offsetof(gpu::GpuLight, intensity) == 16);
static_assert(offsetof(gpu::GpuLight, attenuation) == 32);
static_assert(offsetof(gpu::FrameData, ambient) == 64);
static_assert(offsetof(gpu::FrameData, lights) == 80);
static_assert(offsetof(gpu::FrameData, viewToWorld) == 80 + 48 * MAX_LIGHTS);
static_assert(sizeof(gpu::FrameData) == 80 + 48 * MAX_LIGHTS + 64);
static_assert(offsetof(gpu::ObjectData, normalMatrix) == 64);
static_assert(sizeof(gpu::ObjectData) == 128);
static_assert(offsetof(gpu::DrawConstants, kd) == 16);
static_assert(offsetof(gpu::DrawConstants, object) == 48);
static_assert(offsetof(gpu::DrawConstants, texturing) == 64);
static_assert(offsetof(gpu::DrawConstants, optics) == 80);
static_assert(offsetof(gpu::DrawConstants, diffuseUv) == 96);
static_assert(offsetof(gpu::DrawConstants, normalUv) == 112);
// All of the 128 bytes Vulkan guarantees (and lavapipe offers): a new field
// has to share a vec4's spare component or move to a buffer.
static_assert(sizeof(gpu::DrawConstants) == 128);
static_assert(offsetof(gpu::ShadowData, cube) == 16 * MAX_LIGHTS);
static_assert(offsetof(gpu::ShadowData, bias) == 32 * MAX_LIGHTS);
static_assert(offsetof(gpu::ShadowData, eyeToLight) == 32 * MAX_LIGHTS + 16);
static_assert(offsetof(gpu::ShadowData, lookup) == 32 * MAX_LIGHTS + 16 + 64 * MAX_LIGHTS);
static_assert(sizeof(gpu::ShadowData) == 32 * MAX_LIGHTS + 16 + 80 * MAX_LIGHTS);
static_assert(sizeof(gpu::SkyParameters) == 96);
static_assert(offsetof(gpu::SkyParameters, face) == 80);
static_assert(sizeof(gpu::SkyboxConstants) == 80);
static_assert(sizeof(gpu::PanoramaParameters) == 32);

namespace {

// Triangle order for the device: first for the post-transform vertex cache
// (lavapipe shades vertices on one thread, so re-used vertices are the big
// win on dense meshes), then front-to-back-ish clusters against overdraw
// (1.05 lets a cluster cost 5% more cache misses). Only the order of
// triangles changes, never which ones, their winding or the vertices, so the
// scene stays as authored and tests can index its meshes.
std::vector<uint32_t> deviceTriangleOrder(const Mesh& mesh) {
  std::vector<uint32_t> order(mesh.indices.size());
  if (mesh.indices.empty()) return order;
  meshopt_optimizeVertexCache(order.data(), mesh.indices.data(), mesh.indices.size(),
                              mesh.vertices.size());
  meshopt_optimizeOverdraw(order.data(), order.data(), order.size(), &mesh.vertices[0].position.x,
                           mesh.vertices.size(), sizeof(Vertex), 1.05f);
  return order;
}

// Custom meshes (glTF without TANGENT) may come without tangents.
bool hasTangents(const Mesh& mesh) {
  return std::all_of(mesh.vertices.begin(), mesh.vertices.end(), [](const Vertex& vertex) {
    return glm::dot(glm::vec3(vertex.tangent), glm::vec3(vertex.tangent)) > 0.0f;
  });
}

}  // namespace

GpuScene uploadScene(const Context& context, const Scene& scene, bool detailChains) {
  GpuScene gpuScene;
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  auto append = [&](const Mesh& mesh) {
    DrawItem range{
        uint32_t(indices.size()), uint32_t(mesh.indices.size()), int32_t(vertices.size()), {}};
    vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    std::vector<uint32_t> order = deviceTriangleOrder(mesh);
    indices.insert(indices.end(), order.begin(), order.end());
    return range;
  };
  // A loaded mesh's levels index its own vertices, after its full range; a
  // procedural shape's are whole meshes of their own. A UV-projected copy
  // (`projection`) of a loaded mesh has the same vertices in the same order,
  // so its levels are the mesh's (`meshLevels`) over the copy's vertices; a
  // procedural shape's levels are projected like the copy.
  auto appendLevels = [&](const Mesh& mesh, const ShapeDesc& shape, DrawItem& range,
                          UvProjection projection = UvProjection::Mesh,
                          const DrawItem* meshLevels = nullptr) {
    range.firstLevel = uint32_t(gpuScene.levels.size());
    if (shape.kind == ShapeKind::Custom && meshLevels) {
      for (uint32_t i = 0; i < meshLevels->levelCount; ++i) {
        DrawLevel level = gpuScene.levels[meshLevels->firstLevel + i];
        level.vertexOffset = range.vertexOffset;
        gpuScene.levels.push_back(level);
      }
    } else if (shape.kind == ShapeKind::Custom) {
      for (MeshLevel& level : simplifiedLevels(mesh)) {
        gpuScene.levels.push_back({uint32_t(indices.size()), uint32_t(level.indices.size()),
                                   range.vertexOffset, level.error});
        indices.insert(indices.end(), level.indices.begin(), level.indices.end());
      }
    } else {
      for (const ShapeLevel& level : tessellationLevels(shape)) {
        Mesh coarser = buildShape(level.shape);
        if (projection != UvProjection::Mesh)
          applyUvProjection(coarser, projection, computeBounds(mesh));
        if (!hasTangents(coarser)) computeTangents(coarser);
        DrawItem part = append(coarser);
        gpuScene.levels.push_back(
            {part.firstIndex, part.indexCount, part.vertexOffset, level.error});
      }
    }
    range.levelCount = uint32_t(gpuScene.levels.size()) - range.firstLevel;
  };
  std::vector<DrawItem> meshRanges;
  std::vector<Bounds> meshBounds;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    meshBounds.push_back(computeBounds(mesh));
    if (!hasTangents(mesh)) {
      Mesh withTangents = mesh;
      computeTangents(withTangents);
      meshRanges.push_back(append(withTangents));
    } else {
      meshRanges.push_back(append(mesh));
    }
    // A retessellated shape's chain starts below the tessellation it was built at.
    if (detailChains && m < scene.shapes.size())
      appendLevels(mesh, scaledShape(scene.shapes[m], scene.tessellationScale), meshRanges.back());
  }
  // One projected copy per (mesh, projection) in use.
  std::map<std::pair<uint32_t, UvProjection>, DrawItem> projectedRanges;
  for (const Object& object : scene.objects) {
    UvProjection projection = object.material.uvProjection;
    if (projection == UvProjection::Mesh || projectedRanges.count({object.mesh, projection}))
      continue;
    Mesh projected = scene.meshes[object.mesh];
    applyUvProjection(projected, projection);
    DrawItem range = append(projected);
    if (detailChains && object.mesh < scene.shapes.size())
      appendLevels(projected, scaledShape(scene.shapes[object.mesh], scene.tessellationScale),
                   range, projection, &meshRanges[object.mesh]);
    projectedRanges[{object.mesh, projection}] = range;
  }
  gpuScene.lights = lightLayoutOf(scene);
  gpuScene.vertices =
      uploadBuffer(context, std::as_bytes(std::span(vertices)), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  gpuScene.indices =
      uploadBuffer(context, std::as_bytes(std::span(indices)), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  // Whether a texture has a texel that is not opaque, found once per texture.
  std::vector<int8_t> translucentTexels(scene.textures.size(), -1);
  auto hasTranslucentTexels = [&](int32_t index) {
    int8_t& known = translucentTexels[size_t(index)];
    if (known < 0) {
      const std::vector<uint8_t>& rgba = scene.textures[size_t(index)].rgba8;
      known = 0;
      for (size_t a = 3; a < rgba.size() && !known; a += 4) known = rgba[a] < 255;
    }
    return known == 1;
  };
  for (uint32_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    const Material& material = object.material;
    // glTF BLEND over a texture with alpha: blended by the texel's alpha too.
    const bool alphaFromTexel = material.alphaCoverage && material.diffuseMap.present() &&
                                hasTranslucentTexels(material.diffuseMap.texture);
    DrawItem draw = material.uvProjection == UvProjection::Mesh
                        ? meshRanges[object.mesh]
                        : projectedRanges.at({object.mesh, material.uvProjection});
    // MASK: factor alpha x texel alpha < cutoff <=> texel alpha < cutoff / factor
    // alpha, one threshold for the shader (above 1: nothing is left).
    draw.masked = material.alphaCutoff > 0.0f;
    float threshold = 0.0f;
    if (draw.masked)
      threshold = material.alpha > 0.0f ? material.alphaCutoff / material.alpha : 2.0f;
    draw.hidden = draw.masked && threshold > 1.0f && !material.diffuseMap.present();
    draw.doubleSided = material.doubleSided;
    draw.constants.ka = glm::vec4(material.ka, threshold);
    // kd.w is the opacity the fragment shaders write as alpha.
    draw.constants.kd = glm::vec4(material.kd, 1.0f - material.transparency);
    draw.constants.ks = glm::vec4(material.ks, material.shininess);
    const UvTransform& diffuseUv = material.diffuseMap.transform;
    const UvTransform& normalUv = material.normalMap.transform;
    bool uvTransform = !diffuseUv.identity() || !normalUv.identity();
    int32_t maps = (material.diffuseMap.present() ? TEXTURE_DIFFUSE : 0) |
                   (material.normalMap.present() ? TEXTURE_NORMAL : 0) |
                   (material.heightMap.present() ? TEXTURE_HEIGHT : 0) |
                   (uvTransform ? TEXTURE_UV_TRANSFORM : 0) | (alphaFromTexel ? TEXTURE_ALPHA : 0);
    draw.constants.object = glm::ivec4(int(i), maps, object.receivesShadows ? 1 : 0,
                                       int32_t(packEmissive(material.emissive)));
    draw.castsShadows = object.castsShadows;
    draw.instanceGroup = object.instanceGroup;
    // The largest factor the transform stretches a length by.
    draw.objectScale = std::max({glm::length(glm::vec3(object.transform[0])),
                                 glm::length(glm::vec3(object.transform[1])),
                                 glm::length(glm::vec3(object.transform[2]))});
    draw.constants.texturing = glm::vec4(material.uvScale, material.bumpScale, diffuseUv.rotation);
    // A coverage material (glTF BLEND) is blended, never refracted by the
    // environment term: no kt for it (forward_fragment.glsl writes its opacity).
    draw.constants.optics =
        glm::vec4(material.reflectivity, material.alphaCoverage ? 0.0f : material.transparency,
                  material.ior, normalUv.rotation);
    draw.constants.diffuseUv = glm::vec4(diffuseUv.offset, diffuseUv.scale);
    draw.constants.normalUv = glm::vec4(normalUv.offset, normalUv.scale);
    draw.textured = maps != 0;
    // UV-projected copies share the mesh's positions, so its box.
    draw.worldBounds = transformBounds(meshBounds[object.mesh], object.transform);
    draw.transparent = material.transparency > 0.0f || alphaFromTexel;
    gpuScene.anyTransparent |= draw.transparent;
    gpuScene.anyTextured |= draw.textured;
    gpuScene.anyMasked |= draw.masked;
    gpuScene.anyDoubleSided |= draw.doubleSided;
    gpuScene.bounds = i == 0 ? draw.worldBounds : unite(gpuScene.bounds, draw.worldBounds);
    gpuScene.draws.push_back(draw);
    gpuScene.triangles += draw.indexCount / 3;
  }
  // batchInstances merges a group's draws on their group and index range
  // alone: a copy whose draw differs otherwise (code that edited one copy's
  // material, say) is drawn on its own instead.
  for (DrawItem& draw : gpuScene.draws) {
    if (draw.instanceGroup == Object::kNotInstanced) continue;
    const DrawItem& first = gpuScene.draws[draw.instanceGroup];
    gpu::DrawConstants constants = draw.constants;
    constants.object.x = first.constants.object.x;
    bool same = std::memcmp(&constants, &first.constants, sizeof constants) == 0 &&
                draw.firstIndex == first.firstIndex && draw.indexCount == first.indexCount &&
                draw.vertexOffset == first.vertexOffset && draw.textured == first.textured &&
                draw.material == first.material && draw.transparent == first.transparent &&
                draw.castsShadows == first.castsShadows && draw.masked == first.masked &&
                draw.hidden == first.hidden && draw.doubleSided == first.doubleSided &&
                draw.firstLevel == first.firstLevel && draw.levelCount == first.levelCount;
    if (!same) draw.instanceGroup = Object::kNotInstanced;
  }
  // One set of outlines per texture, wrap modes and cut-off (a scene may
  // have thousands of billboards of one material).
  std::map<std::tuple<int32_t, TextureWrap, TextureWrap, float>,
           std::vector<std::optional<BillboardOutline>>>
      outlines;
  for (const Billboard& billboard : scene.billboards) {
    const TextureSlot& map = billboard.material.diffuseMap;
    bool blended = billboard.alpha == BillboardAlpha::Blend;
    float cutoff = blended ? 0.0f : billboard.material.alphaCutoff;
    glm::uvec2 texels(0);
    std::vector<std::optional<BillboardOutline>> trimmed;
    // A uv scale other than 1 tiles the texture across the quad: not trimmed.
    if (map.present() && size_t(map.texture) < scene.textures.size() &&
        billboard.material.uvScale == glm::vec2(1.0f) && (blended || cutoff > 0.0f)) {
      const Texture& texture = scene.textures[size_t(map.texture)];
      texels = glm::uvec2(texture.width, texture.height);
      auto key = std::make_tuple(map.texture, map.sampler.wrapU, map.sampler.wrapV, cutoff);
      auto found = outlines.find(key);
      if (found == outlines.end() && outlines.size() < kMaxOutlineSets)
        found = outlines.emplace(key, billboardOutlines(texture, map.sampler, cutoff)).first;
      if (found != outlines.end()) trimmed = found->second;
    }
    gpuScene.billboards.push_back(gpuBillboard(billboard, std::move(trimmed), texels));
    gpuScene.billboardInstances += uint32_t(billboard.instances.size());
  }
  std::vector<uint32_t> order = gpuLightOrder(scene);
  gpuScene.shadowFirstLayer.fill(-1);
  for (size_t slot = 0; slot < order.size(); ++slot) {
    const Light& light = scene.lights[order[slot]];
    if (!light.shadows) continue;
    gpuScene.shadowFirstLayer[slot] = int32_t(gpuScene.shadowLayers);
    gpuScene.shadowLayers += light.type == LightType::Point ? 6 : 1;
  }
  return gpuScene;
}

GpuBillboard gpuBillboard(const Billboard& billboard,
                          std::vector<std::optional<BillboardOutline>> outlines,
                          glm::uvec2 texels) {
  const Material& material = billboard.material;
  GpuBillboard out;
  out.outlines = std::move(outlines);
  out.texels = texels;
  out.filter = material.diffuseMap.sampler.filter;
  out.blended = billboard.alpha == BillboardAlpha::Blend;
  out.up = billboard.axis;
  out.constants.ka = glm::vec4(material.ka, out.blended ? 0.0f : material.alphaCutoff);
  out.constants.kd = glm::vec4(material.kd, 1.0f - material.transparency);
  out.constants.ks = glm::vec4(material.ks, material.shininess);
  int32_t maps = (material.diffuseMap.present() ? TEXTURE_DIFFUSE : 0) |
                 (material.normalMap.present() ? TEXTURE_NORMAL : 0) |
                 (material.heightMap.present() ? TEXTURE_HEIGHT : 0);
  out.constants.object = glm::ivec4(0, maps, billboard.receivesShadows ? 1 : 0,
                                    int32_t(packEmissive(material.emissive)));
  out.constants.texturing = glm::vec4(material.uvScale, material.bumpScale, 0.0f);
  int32_t kind = billboard.kind == BillboardKind::Screen      ? BILLBOARD_SCREEN
                 : billboard.kind == BillboardKind::Spherical ? BILLBOARD_SPHERICAL
                                                              : BILLBOARD_CYLINDRICAL;
  out.kind = billboard.kind;
  out.constants.optics = glm::vec4(float(kind), anchorHeight(billboard.anchor), 0.0f, 0.0f);
  out.instances.reserve(billboard.instances.size());
  for (const glm::mat4& matrix : billboard.instances)
    out.instances.push_back(billboardPlacement(billboard, matrix));
  return out;
}

std::vector<DrawItem> visibleDraws(const GpuScene& scene, const glm::mat4& view,
                                   const glm::mat4& projection, bool cull, bool frontToBack,
                                   uint32_t& culled) {
  Frustum frustum = frustumFromMatrix(projection * view);
  std::vector<std::pair<float, DrawItem>> opaque;       // (eye-space z, draw)
  std::vector<std::pair<float, DrawItem>> transparent;  // (eye-space z, draw)
  culled = 0;
  for (const DrawItem& draw : scene.draws) {
    if (cull && !boxIntersectsFrustum(draw.worldBounds, frustum)) {
      ++culled;
      continue;
    }
    float z = (view * glm::vec4(centre(draw.worldBounds), 1.0f)).z;
    (draw.transparent ? transparent : opaque).emplace_back(z, draw);
  }
  // Eye space looks down -z: the largest z is the nearest. Opaque draws go
  // front to back, so early depth testing skips the fragments they hide
  // (on `default` the floor was drawn first and shaded under every object:
  // 1 ms of a 7.5 ms Phong frame); transparent ones back to front. Ties
  // keep scene order (stable sort), so the order never depends on the
  // sort's whims; only coplanar pixels (a box resting on the floor) can
  // change with it.
  if (frontToBack)
    std::stable_sort(opaque.begin(), opaque.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
  std::stable_sort(transparent.begin(), transparent.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<DrawItem> draws;
  draws.reserve(opaque.size() + transparent.size());
  for (const auto& [z, draw] : opaque) draws.push_back(draw);
  for (const auto& [z, draw] : transparent) draws.push_back(draw);
  return draws;
}

uint32_t chooseDrawLevel(std::span<const DrawLevel> levels, const DrawItem& draw,
                         const ViewSize& view, uint32_t previous, float bound, float hysteresis,
                         std::vector<float>& projected) {
  // Pixels per world unit at the nearest point of the object's box.
  float pixels =
      pixelsPerUnitForSphere(view, centre(draw.worldBounds), boundingRadius(draw.worldBounds)) *
      draw.objectScale;
  projected.assign(1, 0.0f);
  for (uint32_t i = 0; i < draw.levelCount; ++i)
    projected.push_back(levels[draw.firstLevel + i].error * pixels);
  return chooseLevel(projected, previous, bound, hysteresis);
}

void batchInstances(std::vector<DrawItem>& draws, std::vector<gpu::ObjectData>& objects) {
  // A batch is keyed by its group and index range (the level drawn).
  using Key = std::tuple<uint32_t, uint32_t, int32_t>;
  auto keyOf = [](const DrawItem& draw) {
    return Key{draw.instanceGroup, draw.firstIndex, draw.vertexOffset};
  };
  std::map<Key, std::vector<uint32_t>> members;  // object indices, in draw order
  for (const DrawItem& draw : draws)
    if (!draw.transparent && draw.instanceGroup != Object::kNotInstanced)
      members[keyOf(draw)].push_back(uint32_t(draw.constants.object.x));
  if (members.empty()) return;
  std::vector<DrawItem> batched;
  batched.reserve(draws.size());
  for (const DrawItem& draw : draws) {
    if (draw.transparent || draw.instanceGroup == Object::kNotInstanced) {
      batched.push_back(draw);
      continue;
    }
    auto found = members.find(keyOf(draw));
    if (found == members.end()) continue;  // recorded with the group's first copy
    DrawItem batch = draw;
    batch.constants.object.x = int32_t(objects.size());
    batch.instanceCount = uint32_t(found->second.size());
    for (uint32_t object : found->second) {
      gpu::ObjectData copy = objects[object];  // push_back may move what it reads
      objects.push_back(copy);
    }
    batched.push_back(batch);
    members.erase(found);
  }
  draws = std::move(batched);
}

LightLayout lightLayoutOf(const Scene& scene) {
  LightLayout layout;
  size_t count = std::min<size_t>(scene.lights.size(), MAX_LIGHTS);
  for (size_t i = 0; i < count; ++i) {
    const Light& light = scene.lights[i];
    ++(light.type == LightType::Point ? layout.point : layout.directional);
    if (light.type == LightType::Point && light.attenuation != glm::vec3(1.0f, 0.0f, 0.0f))
      layout.attenuated = true;
  }
  // In FrameData's order: point lights first, then directional ones.
  uint32_t slot = 0;
  for (LightType type : {LightType::Point, LightType::Directional})
    for (size_t i = 0; i < count; ++i)
      if (scene.lights[i].type == type) {
        if (scene.lights[i].shadows) layout.shadowed |= 1u << slot;
        ++slot;
      }
  return layout;
}

uint32_t packEmissive(glm::vec3 emissive) {
  constexpr int kMantissaBits = 9, kBias = 15, kMaxExponent = 31;
  const float largest = std::ldexp(511.0f / 512.0f, kMaxExponent - kBias);  // 65408
  glm::vec3 c;
  for (int i = 0; i < 3; ++i)  // !(x > 0) also catches NaN
    c[i] = !(emissive[i] > 0.0f) ? 0.0f : std::min(emissive[i], largest);
  const float most = std::max({c.r, c.g, c.b});
  if (most == 0.0f) return 0;
  int exponent = 0;
  std::frexp(most, &exponent);  // most = f 2^exponent, f in [0.5, 1): floor(log2) = exponent - 1
  int shared = std::max(-kBias - 1, exponent - 1) + 1 + kBias;
  float step = std::ldexp(1.0f, shared - kBias - kMantissaBits);
  if (std::floor(most / step + 0.5f) == float(1 << kMantissaBits)) {
    step *= 2.0f;
    ++shared;
  }
  auto mantissa = [&](float value) { return uint32_t(std::floor(value / step + 0.5f)); };
  return mantissa(c.r) | mantissa(c.g) << 9 | mantissa(c.b) << 18 | uint32_t(shared) << 27;
}

glm::vec3 unpackEmissive(uint32_t bits) {
  const int exponent = int(bits >> 27) - 15 - 9;
  return {std::ldexp(float(bits & 511u), exponent), std::ldexp(float((bits >> 9) & 511u), exponent),
          std::ldexp(float((bits >> 18) & 511u), exponent)};
}

std::vector<uint32_t> gpuLightOrder(const Scene& scene) {
  std::vector<uint32_t> order;
  uint32_t count = lightLayoutOf(scene).total();
  for (LightType type : {LightType::Point, LightType::Directional})
    for (uint32_t i = 0; i < count; ++i)
      if (scene.lights[i].type == type) order.push_back(i);
  return order;
}

gpu::FrameData makeFrameData(const Scene& scene, const glm::mat4& view,
                             const glm::mat4& projection) {
  gpu::FrameData frame{};
  frame.projection = projection;
  frame.ambient = glm::vec4(scene.ambient, 0.0f);
  // The view is a rigid lookAt: its rotation's inverse is the transpose.
  frame.viewToWorld = glm::mat4(glm::transpose(glm::mat3(view)));
  LightLayout layout = lightLayoutOf(scene);
  uint32_t nextPoint = 0, nextDirectional = layout.point;
  for (size_t i = 0; i < layout.total(); ++i) {
    const Light light = lightInView(scene.lights[i], view);
    const bool point = light.type == LightType::Point;
    gpu::GpuLight& out = frame.lights[point ? nextPoint++ : nextDirectional++];
    // The shader wants a directional light's unit direction *towards* it.
    out.position = point ? glm::vec4(light.position, 1.0f) : glm::vec4(-light.direction, 0.0f);
    out.intensity = glm::vec4(light.intensity, 0.0f);
    out.attenuation = glm::vec4(light.attenuation, 0.0f);
  }
  return frame;
}

LightValues lightValuesOf(const gpu::FrameData& frame) {
  LightValues values{};
  size_t next = 0;
  auto put = [&](const glm::vec4& v) {
    for (int c = 0; c < 3; ++c) values[next++] = std::bit_cast<uint32_t>(v[c]);
  };
  put(frame.ambient);
  for (const gpu::GpuLight& light : frame.lights) {
    put(light.position);
    put(light.intensity);
    put(light.attenuation);
  }
  return values;
}

ShadowFrame makeShadowFrame(const Scene& scene, const GpuScene& gpuScene, const glm::mat4& view,
                            const glm::mat4& projection, const ShadowBias& bias, uint32_t mapSize) {
  ShadowFrame frame;
  frame.worldToLightClip.resize(gpuScene.shadowLayers);
  frame.layerLights.resize(gpuScene.shadowLayers);
  frame.data.bias = glm::vec4(bias.constant, bias.slope, bias.normalOffset, 0.0f);
  glm::mat4 eyeToWorld = glm::inverse(view);
  std::vector<uint32_t> order = gpuLightOrder(scene);
  // A PCF5 tap reaches 2 texels out (and a bias a few more): a point
  // light's faces overlap by that much, so taps at an edge stay in the face.
  constexpr float kCubeMarginTexels = 4.0f;
  for (size_t slot = 0; slot < order.size(); ++slot) {
    int32_t first = gpuScene.shadowFirstLayer[slot];
    frame.data.lights[slot] = glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f);
    if (first < 0) continue;
    const Light& light = scene.lights[order[slot]];
    ShadowView shadowView =
        light.type == LightType::Point
            ? pointShadowView(light, gpuScene.bounds, mapSize, kCubeMarginTexels)
            : directionalShadowView(light, gpuScene.bounds, projection * view, mapSize);
    frame.data.lights[slot] =
        glm::vec4(float(first), shadowView.texelSize, 1.0f / float(mapSize), 0.0f);
    frame.data.cube[slot] = shadowView.cube;
    if (light.type == LightType::Directional) {
      glm::mat4 eyeToLight = shadowView.viewProjection[0] * eyeToWorld;
      frame.data.eyeToLight[slot] = eyeToLight;
      // Moving a point one texel towards the light changes only its depth
      // in the light's orthographic view (the view looks along the light).
      glm::vec3 towardsLight = glm::normalize(-glm::mat3(view) * light.direction);
      float depthPerTexel = (eyeToLight * glm::vec4(towardsLight, 0.0f)).z * shadowView.texelSize;
      frame.data.lookup[slot] =
          glm::vec4(depthPerTexel * bias.constant, depthPerTexel * bias.slope, depthPerTexel, 0.0f);
    } else {
      // A texel at distance d is texelSize * d: moving t texels towards the
      // light scales the vector from it by 1 - texelSize * t.
      frame.data.lookup[slot] = glm::vec4(1.0f - shadowView.texelSize * bias.constant,
                                          shadowView.texelSize * bias.slope, 0.0f, 0.0f);
    }
    glm::vec4 layerLight = light.type == LightType::Point
                               ? glm::vec4(light.position, 1.0f)
                               : glm::vec4(-glm::normalize(light.direction), 0.0f);
    for (size_t face = 0; face < shadowView.viewProjection.size(); ++face) {
      frame.worldToLightClip[size_t(first) + face] = shadowView.viewProjection[face];
      frame.layerLights[size_t(first) + face] = layerLight;
    }
  }
  return frame;
}

std::vector<gpu::ObjectData> makeObjectData(const Scene& scene, const glm::mat4& view,
                                            NormalTransform normals) {
  std::vector<gpu::ObjectData> objects;
  objects.reserve(scene.objects.size());
  for (const Object& object : scene.objects) {
    gpu::ObjectData data{};
    data.modelView = view * object.transform;
    data.normalMatrix = normals == NormalTransform::InverseTranspose
                            ? glm::mat4(normalMatrix(data.modelView))
                            : glm::mat4(glm::mat3(data.modelView));
    objects.push_back(data);
  }
  return objects;
}

}  // namespace shadelab
