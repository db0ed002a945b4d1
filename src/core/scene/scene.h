#pragma once
// The scene model of DESIGN.md: a camera, an ambient light, point and
// directional lights, and objects (a mesh, a transform and a material).
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/names.h"
#include "core/scene/environment.h"
#include "core/scene/mesh.h"
#include "core/scene/shape.h"

namespace shadelab {

enum class Projection { Perspective, Frustum, Orthographic };
inline constexpr NameTable<Projection, 3> kProjectionNames = {
    {{Projection::Perspective, "perspective"},
     {Projection::Frustum, "frustum"},
     {Projection::Orthographic, "orthographic"}}};

struct Camera {
  glm::vec3 eye{0.0f, 2.0f, 6.0f};
  glm::vec3 at{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  Projection projection = Projection::Perspective;
  float fovyDegrees = 45.0f;  // perspective
  float near = 0.1f;
  float far = 100.0f;
  // Frustum: the window on the near plane; orthographic: the view volume's sides.
  float left = -1.0f, right = 1.0f, bottom = -1.0f, top = 1.0f;

  glm::mat4 viewMatrix() const;
  // Vulkan clip space (y down, depth 0..1); `aspect` is width / height and
  // applies to the perspective projection only. reversedZ maps near to 1, far to 0.
  glm::mat4 projectionMatrix(float aspect, bool reversedZ = false) const;
};

// What makes a camera unusable, if anything: the field at fault ("eye",
// "at", "up", "far", "right", "top"), what is wrong and what was expected.
// One check for the scene format and the command line.
struct CameraProblem {
  std::string field;
  std::string problem;
  std::string expected;
};
std::optional<CameraProblem> findCameraProblem(const Camera& camera);
// The camera as command-line options that reproduce it on the scene it came
// from: "--eye X,Y,Z --at X,Y,Z --up X,Y,Z --fovy DEG", numbers that read
// back to the same floats. What the viewer prints and saves with screenshots.
std::string cameraOptionLine(const Camera& camera);
// The camera as the scene format's "camera" object (one line of JSON), ready
// to paste into a scene file.
std::string cameraJson(const Camera& camera);

enum class LightType { Point, Directional };
inline constexpr NameTable<LightType, 2> kLightTypeNames = {
    {{LightType::Point, "point"}, {LightType::Directional, "directional"}}};

struct Light {
  LightType type = LightType::Point;
  glm::vec3 position{0.0f, 5.0f, 0.0f};     // point lights, world space
  glm::vec3 direction{0.0f, -1.0f, 0.0f};   // directional lights: the direction light travels
  glm::vec3 intensity{1.0f};                // Ip per RGB channel
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // f_att = 1 / (a + b d + c d^2)
  bool shadows = true;  // casts shadows (a shadow map) when the frame's shadow method is on
};

// Texture sampling, per texture slot of a material (glTF samplers map here).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };
inline constexpr NameTable<TextureWrap, 3> kTextureWrapNames = {
    {{TextureWrap::Repeat, "repeat"},
     {TextureWrap::ClampToEdge, "clamp_to_edge"},
     {TextureWrap::MirroredRepeat, "mirrored_repeat"}}};
// The --filter and JSON "filter" names.
enum class TextureFilter { Nearest, Bilinear, Trilinear, Anisotropic };
inline constexpr NameTable<TextureFilter, 4> kTextureFilterNames = {
    {{TextureFilter::Nearest, "nearest"},
     {TextureFilter::Bilinear, "bilinear"},
     {TextureFilter::Trilinear, "trilinear"},
     {TextureFilter::Anisotropic, "aniso"}}};
struct SamplerDesc {
  TextureWrap wrapU = TextureWrap::Repeat;
  TextureWrap wrapV = TextureWrap::Repeat;
  TextureFilter filter = TextureFilter::Trilinear;
  float maxAnisotropy = 8.0f;  // Anisotropic only: 2..16
  auto operator<=>(const SamplerDesc&) const = default;
};

// A texture's texels as loaded or generated, before upload: 8-bit RGBA, row 0
// at the top. Colour textures hold sRGB-encoded values (sampled through an
// _SRGB format, so shaders see linear values); data textures (normal and
// height maps) are linear.
struct Texture {
  std::string name;  // the file or generator it came from, for messages
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;  // width * height * 4
  bool srgb = true;
};

// Texture coordinates generated for a material instead of the mesh's own
// (an S-mapping, for meshes without UVs): see core/scene/uv_mapping.h.
enum class UvProjection { Mesh, Planar, Cylindrical, Spherical, Box };
inline constexpr NameTable<UvProjection, 5> kUvProjectionNames = {
    {{UvProjection::Mesh, "mesh"},
     {UvProjection::Planar, "planar"},
     {UvProjection::Cylindrical, "cylindrical"},
     {UvProjection::Spherical, "spherical"},
     {UvProjection::Box, "box"}}};

// A material's use of one texture: an index into Scene::textures (-1: none).
// glTF's KHR_texture_transform, in the uv space the texture is sampled in
// (glTF's: origin at the image's top left): uv' = T(offset) R(rotation) S(scale) uv,
// R = [[cos, sin], [-sin, cos]].
struct UvTransform {
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;  // radians
  glm::vec2 scale{1.0f};
  bool identity() const {
    return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f);
  }
};

struct TextureSlot {
  int32_t texture = -1;
  SamplerDesc sampler;
  UvTransform transform;  // the rasteriser applies it to the diffuse and normal maps
  bool present() const { return texture >= 0; }
};

// The Phong material: I = Ia ka + sum f_att Ip [kd (N.L) + ks (R.V)^n], plus the
// terms the ray tracer and environment mapping add: a mirror fraction, a
// transmitted fraction with its index of refraction, and emitted light.
struct Material {
  glm::vec3 ka{0.1f};
  glm::vec3 kd{0.7f};
  glm::vec3 ks{0.3f};
  float shininess = 32.0f;
  float reflectivity = 0.0f;  // kr: fraction of the reflected ray's colour added, 0..1
  float transparency = 0.0f;  // kt: fraction of the refracted ray's colour added, 0..1
  float ior = 1.5f;           // index of refraction of the inside; the outside is 1 (air)
  // glTF alphaMode BLEND (and blended billboards, as the tracer takes them):
  // kt is 1 - coverage, a share of the pixel the surface does not cover; a
  // diffuse map's alpha scales the coverage. The tracer then weighs the local colour by the
  // coverage and sees the rest straight through (no refraction, no Fresnel),
  // as the rasteriser's alpha blend does; otherwise kt is Whitted's
  // transmission, added to the full local colour.
  bool alphaCoverage = false;
  glm::vec3 emissive{0.0f};  // added unlit
  TextureSlot diffuseMap;    // multiplies kd (and ka)
  TextureSlot normalMap;     // tangent space, xyz = 2 * rgb - 1
  TextureSlot heightMap;     // r = height; the normal is perturbed by its derivatives
  float bumpScale = 1.0f;    // normal map xy scale / height map amplitude
  UvProjection uvProjection = UvProjection::Mesh;  // where the UVs come from
  glm::vec2 uvScale{1.0f};                         // texture repeats per unit of UV (tiling)
  // glTF alphaMode MASK: fragments whose alpha (`alpha` times the diffuse
  // texel's alpha) is below alphaCutoff are not drawn, nor cast shadows; 0: no test.
  float alphaCutoff = 0.0f;
  float alpha = 1.0f;        // glTF baseColorFactor's alpha, for the MASK test
  bool doubleSided = false;  // glTF doubleSided: not culled, back faces lit with -N
};

struct Object {
  std::string name;
  uint32_t mesh = 0;  // index into Scene::meshes
  // A transform that mirrors (negative determinant) needs a mesh wound for
  // it (reverseWinding, ShapeDesc::mirrored), as the loaders give it: its
  // triangles then wind counter-clockwise seen from outside once placed.
  glm::mat4 transform{1.0f};
  Material material;
  bool castsShadows = true;     // drawn into the shadow maps
  bool receivesShadows = true;  // its lighting looks the shadow maps up
  // The copies one "instances" block makes are objects of their own (the
  // tracer, culling, levels of detail and shadows see each), with the index
  // of the first copy here: the renderer draws the visible copies of a group
  // at one level as one instanced draw. kNotInstanced: an object alone.
  uint32_t instanceGroup = kNotInstanced;
  static constexpr uint32_t kNotInstanced = ~0u;
};

// A billboard: a textured quad that turns towards the viewer, drawn by the
// billboard pass (passes/billboard_pass.h), once per instance in one draw.
enum class BillboardKind { Screen, Spherical, Cylindrical };
inline constexpr NameTable<BillboardKind, 3> kBillboardKindNames = {
    {{BillboardKind::Screen, "screen"},
     {BillboardKind::Spherical, "spherical"},
     {BillboardKind::Cylindrical, "cylindrical"}}};
// Where the instance's position sits on the quad: its centre, or the middle
// of its bottom edge (a tree standing on the ground).
enum class BillboardAnchor { Center, Bottom };
inline constexpr NameTable<BillboardAnchor, 2> kBillboardAnchorNames = {
    {{BillboardAnchor::Center, "center"}, {BillboardAnchor::Bottom, "bottom"}}};
// How the texture's alpha applies: cut-out (fragments below the cut-off are
// discarded; opaque, writes depth) or blended (sorted back to front with the
// transparent objects, writes no depth).
enum class BillboardAlpha { Test, Blend };
inline constexpr NameTable<BillboardAlpha, 2> kBillboardAlphaNames = {
    {{BillboardAlpha::Test, "test"}, {BillboardAlpha::Blend, "blend"}}};

struct Billboard {
  std::string name;
  BillboardKind kind = BillboardKind::Spherical;
  BillboardAnchor anchor = BillboardAnchor::Center;
  BillboardAlpha alpha = BillboardAlpha::Test;
  glm::vec2 size{1.0f};  // width and height, world units, before each instance's scale
  // World space: the axis a cylindrical billboard turns about, the up a
  // spherical one keeps (as nearly as it can while facing the eye).
  glm::vec3 axis{0.0f, 1.0f, 0.0f};
  Material material;  // diffuseMap required (colour and alpha); alphaCutoff for Test
  // World matrices, one per copy (at least one). A billboard takes its
  // position (the translation) and its width and height scales (the lengths
  // of the x and y columns) from each; it turns towards the viewer itself,
  // so rotations do not orient it.
  std::vector<glm::mat4> instances;
  bool receivesShadows = true;  // billboards never cast (see billboard_pass.h)
};

struct Scene {
  std::string name;
  std::string description;  // one line, from a scene file's "description"
  Camera camera;
  glm::vec3 ambient{1.0f};     // Ia
  glm::vec3 background{0.0f};  // linear clear colour
  Environment environment;     // what surrounds the scene; none: the background colour
  std::vector<Light> lights;
  std::vector<Mesh> meshes;       // what is drawn
  std::vector<ShapeDesc> shapes;  // parallel to meshes: how each was built (Custom: loaded)
  std::vector<Object> objects;
  std::vector<Texture> textures;  // referenced by Material texture slots
  // Drawn by the billboard pass; the tracer traces the quads it draws for the
  // scene's camera (core/scene/billboard_quad.h).
  std::vector<Billboard> billboards;
  // The factor retessellate last built the procedural meshes at (1 after
  // tessellateForView): their detail chains start from it (uploadScene).
  float tessellationScale = 1.0f;

  uint32_t addMesh(Mesh mesh);  // a custom mesh (kept as is when re-tessellating)
  uint32_t addShape(const ShapeDesc& shape);
  // Rebuilds every procedural mesh at `scale` times its base tessellation.
  void retessellate(float scale);
  uint64_t triangleCount() const;
  // Without building: what the scene would cost if every procedural mesh
  // were rebuilt at `scale`.
  struct Estimate {
    uint64_t drawnTriangles = 0;  // summed over objects
    uint64_t meshBytes = 0;       // each mesh once (objects share meshes)
  };
  Estimate estimate(float scale) const;
};

// The tessellation factors a request may ask for (--tess, bench's --tess,
// compare's tess column, the rows of a bench table --quality reads).
inline constexpr float kMinTessellation = 0.125f;
inline constexpr float kMaxTessellation = 16.0f;

// The default triangle budget of a request (drawn triangles, summed over
// objects): 16 M is ~0.6-1.3 GB of vertex and index data and tens of seconds
// per frame on lavapipe.
inline constexpr uint64_t kDefaultMaxTriangles = 16'000'000;
// Throws InputError naming `request` (e.g. "--tess 16"), the estimate and
// `budgetName` (the option that raises it) when the scene at `scale` would
// draw more than `maxTriangles`.
void checkTriangleBudget(const Scene& scene, float scale, uint64_t maxTriangles,
                         const std::string& request, const std::string& budgetName);

// Built-in scenes need no files: they are assets/scenes/<name>.json embedded
// in the binary. Each throws InputError for an unknown name, listing the
// names that exist.
Scene builtinScene(const std::string& name);
std::vector<std::string> builtinSceneNames();                  // sorted
std::string_view builtinSceneJson(const std::string& name);    // the file's text
std::string builtinSceneDescription(const std::string& name);  // its one line
// The `highlight` scene with its plane cut into quadsPerSide^2 quads.
Scene highlightScene(uint32_t quadsPerSide);
// The `zfight` scene with this projection and near plane (its file's:
// perspective, near 0.1): two large parallel planes kZFightGap apart, far
// from the camera. Unlit colours: the nearer plane kZFightNearColor, the
// farther kZFightFarColor, listed first; black background. The constants
// restate assets/scenes/zfight.json for the measurement (tests check both agree).
inline constexpr float kZFightGap = 0.05f;
inline constexpr glm::vec3 kZFightNearColor{1.0f, 0.0f, 0.0f};
inline constexpr glm::vec3 kZFightFarColor{0.0f, 0.0f, 1.0f};
Scene zfightScene(Projection projection, float near);

// What a scene probably does not mean, worth a warning before drawing it: no
// lights (only ambient and emission show); for the rasteriser
// (`rasteriser`), reflective or transparent materials with no environment
// (its environment term has nothing to show, so they look matte). Empty when
// nothing is suspicious.
std::vector<std::string> sceneWarnings(const Scene& scene, bool rasteriser);

}  // namespace shadelab
