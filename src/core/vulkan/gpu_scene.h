#pragma once
// A scene's geometry on the device (one vertex and one index buffer for all
// meshes) and the per-frame data the shaders read, built from the scene and
// the camera.
#include <array>
#include <compare>
#include <optional>
#include <span>
#include <vector>

#include "core/scene/billboard_outline.h"
#include "core/scene/billboard_quad.h"
#include "core/scene/lod.h"
#include "core/scene/scene.h"
#include "core/scene/shadows.h"
#include "core/vulkan/resources.h"
#include "interface.h"

namespace shadelab {

// How normals go to eye space. Only the inverse transpose keeps them
// perpendicular to the surface under non-uniform scale; the plain
// model-view is the classic mistake, kept so tests can show what it breaks.
enum class NormalTransform { InverseTranspose, ModelView };

struct DrawItem {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  gpu::DrawConstants constants{};  // material and object index, pushed per draw
  bool textured = false;           // the material has a texture: drawn by the textured pipelines
  uint32_t material = 0;     // textured: which material's set 1 it binds (passes/scene_textures)
  Bounds worldBounds;        // the mesh's box, transformed: what culling tests
  bool transparent = false;  // blended after the opaque draws, back to front
  bool castsShadows = true;  // drawn into the shadow maps
  // glTF alphaMode MASK: drawn by the SPEC_ALPHA_MASK variants (threshold in
  // constants.ka.w); `hidden` when the cut-off removes every fragment (an
  // untextured material whose alpha is below it), so no shadow is cast either.
  bool masked = false;
  bool hidden = false;
  bool doubleSided = false;  // glTF doubleSided: drawn without culling, SPEC_DOUBLE_SIDED
  // --lod auto: GpuScene::levels[firstLevel, firstLevel + levelCount) are
  // this draw's coarser levels (none when its mesh has no chain), and
  // objectScale turns their mesh-space errors into world lengths.
  uint32_t firstLevel = 0;
  uint32_t levelCount = 0;
  float objectScale = 1.0f;
  // Object::instanceGroup of its object; batchInstances turns a run of a
  // group's draws into one draw of instanceCount copies, whose ObjectData
  // are consecutive from constants.object.x (the vertex stage adds
  // gl_InstanceIndex).
  uint32_t instanceGroup = Object::kNotInstanced;
  uint32_t instanceCount = 1;
};

// A coarser level of a mesh (core/scene/lod.h): a loaded mesh's simplified
// index range over its own vertices, or a procedural shape rebuilt at a
// lower tessellation with vertices of its own; its error in mesh units. Or
// the object's impostor (passes/impostor_capture.h), always the last level:
// no indices, drawn by the billboard pass as GpuScene::billboards[impostor].
struct DrawLevel {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  float error = 0.0f;
  uint32_t impostor = kNoImpostor;
  static constexpr uint32_t kNoImpostor = ~0u;
};

// --lod auto's choice for one draw with a chain (levels: GpuScene::levels):
// each level's error projected to pixels at the nearest point of the draw's
// box, then chooseLevel (core/scene/lod.h) from `previous` within `bound`
// with `hysteresis`. `projected` is scratch space, kept between calls.
uint32_t chooseDrawLevel(std::span<const DrawLevel> levels, const DrawItem& draw,
                         const ViewSize& view, uint32_t previous, float bound, float hysteresis,
                         std::vector<float>& projected);

// An impostor billboard's atlas (core/scene/impostor.h): textures
// GpuScene::impostorTextures[2 atlas] (coverage) and [2 atlas + 1] (normals),
// captured around `centre` (mesh space), each cell seeing halfSize on either
// side of it.
struct ImpostorAtlas {
  int32_t atlas = -1;  // -1: not an impostor
  glm::vec3 centre{0.0f};
  float halfSize = 0.0f;
  uint32_t cells = 0;
};

// A billboard object as the billboard pass draws it: one instanced draw of
// its placements that survive culling, moved to eye space every frame. An
// impostor billboard has no placements of its own: its copies are the
// objects that chose their impostor level this frame.
struct GpuBillboard {
  // ka.w = alpha cut-off (alpha test), kd.w = opacity (1 - transparency),
  // object.y = TEXTURE_* flags, object.z = receives shadows, texturing as for
  // meshes; optics.x = BILLBOARD_* kind, optics.y = the anchor's height on
  // the quad as a fraction (0 bottom, 0.5 centre); optics.w is set per
  // draw: 1 when its copies are drawn as their trimmed outlines.
  gpu::DrawConstants constants{};
  glm::vec3 up{0.0f, 1.0f, 0.0f};  // world: a cylindrical one's axis, a spherical one's up
  BillboardKind kind = BillboardKind::Spherical;  // optics.x's kind (not impostors)
  uint32_t material = 0;  // set 1 (passes/scene_textures), numbered at upload
  bool blended = false;   // alpha blend: sorted with the transparent draws
  std::vector<BillboardPlacement> instances;
  ImpostorAtlas impostor;
  // Trimmed outlines (core/scene/billboard_outline.h), one per mip level of
  // the diffuse map; empty when the quad is always drawn (no diffuse map,
  // uv scale other than 1, no cut-off, or a texture too large to examine).
  std::vector<std::optional<BillboardOutline>> outlines;
  glm::uvec2 texels{0};                             // the diffuse map's base level size
  TextureFilter filter = TextureFilter::Trilinear;  // its sampler's own
};
// `outlines`: billboardOutlines for this billboard's diffuse map, sampler
// and cut-off (uploadScene shares them between billboards of one material).
GpuBillboard gpuBillboard(const Billboard& billboard,
                          std::vector<std::optional<BillboardOutline>> outlines = {},
                          glm::uvec2 texels = glm::uvec2(0));

// How many lights of each kind the shaders loop over: specialization
// constants, so a pipeline is built per layout (point lights + directional
// lights <= MAX_LIGHTS).
struct LightLayout {
  uint32_t point = 0;
  uint32_t directional = 0;
  bool attenuated = false;  // some point light has attenuation other than (1, 0, 0)
  uint32_t shadowed = 0;    // bit i: FrameData::lights[i] casts shadows (SPEC_SHADOWED_LIGHTS)
  uint32_t total() const { return point + directional; }
  auto operator<=>(const LightLayout&) const = default;
};

// Material::emissive as DrawConstants::object.w holds it: RGB9E5 (9-bit
// mantissas, one 5-bit exponent, the packing of VK_FORMAT_E5B9G9R9_UFLOAT),
// rounded to nearest. Each channel keeps about 1/511 of the largest one (1/512
// but where rounding carries into the next exponent); negative
// and NaN channels become 0, values past 65408 that. unpackEmissive is the
// shaders' drawEmissive() on the host.
uint32_t packEmissive(glm::vec3 emissive);
glm::vec3 unpackEmissive(uint32_t bits);

// The first MAX_LIGHTS lights of the scene, as makeFrameData orders them.
LightLayout lightLayoutOf(const Scene& scene);
// The indices into scene.lights of FrameData::lights, in its order (point lights first).
std::vector<uint32_t> gpuLightOrder(const Scene& scene);

struct GpuScene {
  Buffer vertices;
  Buffer indices;
  std::vector<DrawItem> draws;
  std::vector<DrawLevel> levels;  // every draw's coarser levels (DrawItem::firstLevel)
  uint64_t triangles = 0;
  LightLayout lights;
  bool anyTransparent = false;
  bool anyTextured = false;
  bool anyMasked = false;
  bool anyDoubleSided = false;
  Bounds bounds;  // every object's box: what the shadow maps must cover
  // Shadow-map layers by light, in FrameData::lights' order (point lights
  // first): the first of its layers (six for a point light, one for a
  // directional one), or -1 for a light without shadows.
  std::array<int32_t, MAX_LIGHTS> shadowFirstLayer{};
  uint32_t shadowLayers = 0;
  // Parallel to Scene::billboards, then the impostors' (passes/impostor_capture.h).
  std::vector<GpuBillboard> billboards;
  uint32_t billboardInstances = 0;        // summed over billboards
  std::vector<Texture> impostorTextures;  // two per impostor atlas, uploaded by SceneTextures
  uint32_t impostorDraws = 0;  // draws whose chain ends in an impostor: the most drawn at once
};

// Objects whose material asks for a UV projection draw a copy of their mesh
// with projected UVs; meshes without tangents get computed ones (mesh.h).
// With `detailChains`, every loaded (custom) mesh also gets its chain of
// simplified levels and every curved procedural shape its chain of
// tessellations, for --lod auto (core/scene/lod.h).
GpuScene uploadScene(const Context& context, const Scene& scene, bool detailChains = false);

// The draws of one frame, the one place they are filtered and ordered:
// draws whose box is outside the view frustum are dropped (counted in
// `culled`), then the opaque ones front to back (fewer hidden fragments
// shaded; in scene order without `frontToBack`), then the transparent ones back to front (the
// painter's algorithm; blending is not commutative), both by the eye-space depth of their box's
// centre.
std::vector<DrawItem> visibleDraws(const GpuScene& scene, const glm::mat4& view,
                                   const glm::mat4& projection, bool cull, bool frontToBack,
                                   uint32_t& culled);

// Instancing: the opaque draws of one instance group at one level (the same
// index range) become one draw, recorded where the group's first (nearest)
// copy was, its copies in the order they had. Their ObjectData are appended
// to `objects` so that they are consecutive; transparent draws stay one by
// one (each copy has its place in the back-to-front order). The image is
// the one the draws would give one by one, only the order of the opaque
// draws between copies of a group changes, which a depth test makes moot
// except where copies and other objects are coplanar.
void batchInstances(std::vector<DrawItem>& draws, std::vector<gpu::ObjectData>& objects);

// Lights move to eye space, so the shaders light with V = -position; the
// first MAX_LIGHTS scene lights go in, point lights first, then directional.
gpu::FrameData makeFrameData(const Scene& scene, const glm::mat4& view,
                             const glm::mat4& projection);
// A frame's ambient term and lights as SPEC_LIGHT_VALUES lays them out (float
// bit patterns; unused lights zero): what ForwardFrame::lights compiles in.
using LightValues = std::array<uint32_t, LIGHT_VALUE_WORDS>;
LightValues lightValuesOf(const gpu::FrameData& frame);
// The shadow maps of one frame: what the forward pass reads (ShadowData:
// per light its first layer and texel size, the bias, eye space to each
// layer's clip space) and what the shadow pass draws with (world space to
// each layer's clip space). A directional light's map is fitted to
// `cameraViewProjection`'s frustum within the scene's bounds.
struct ShadowFrame {
  gpu::ShadowData data{};
  std::vector<glm::mat4> worldToLightClip;  // one per layer
  // Per layer, its light in world space: a point light's position (w = 1)
  // or the unit direction towards a directional light (w = 0).
  std::vector<glm::vec4> layerLights;
};
ShadowFrame makeShadowFrame(const Scene& scene, const GpuScene& gpuScene, const glm::mat4& view,
                            const glm::mat4& projection, const ShadowBias& bias, uint32_t mapSize);

// Model-view and its normal matrix (inverse transpose) per object.
// Materials travel with the draws (DrawItem::constants).
std::vector<gpu::ObjectData> makeObjectData(
    const Scene& scene, const glm::mat4& view,
    NormalTransform normals = NormalTransform::InverseTranspose);

}  // namespace shadelab
