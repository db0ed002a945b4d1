// Where each shading method fails, measured on the device readback (linear
// float, before sRGB encoding) and checked against the C++ illumination
// equation in core/scene/lighting.h. Every test asserts a measured quantity; the
// figures are printed so a failing run shows how far off it was.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "core/scene/lighting.h"
#include "core/scene/scene.h"
#include "core/scene/shading.h"
#include "core/scene/transform.h"
#include "core/vulkan/gpu_scene.h"
#include "gpu_test_support.h"
#include "measure/highlight.h"

namespace shadelab::test {
namespace {

constexpr float kOneLevel = 1.0f / 255.0f;  // one step of an 8-bit channel

using ShadingStability = GpuTest;

const ShadingModel kLitModels[] = {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong,
                                   ShadingModel::BlinnPhong};

float largestChannelError(glm::vec3 a, glm::vec3 b) {
  glm::vec3 d = glm::abs(a - b);
  return std::max({d.r, d.g, d.b});
}

// An orthographic camera at z = 10 looking down -z at a square window of
// side 2 * halfSize, so a pixel centre maps to a known (x, y).
Camera orthoCameraDownZ(float halfSize) {
  Camera camera;
  camera.eye = {0.0f, 0.0f, 10.0f};
  camera.at = {0.0f, 0.0f, 0.0f};
  camera.projection = Projection::Orthographic;
  camera.left = camera.bottom = -halfSize;
  camera.right = camera.top = halfSize;
  camera.near = 1.0f;
  camera.far = 20.0f;
  return camera;
}

// World (x, y) of pixel (px, py)'s centre under orthoCameraDownZ; row 0 is the top.
glm::vec2 pixelCentre(uint32_t px, uint32_t py, uint32_t size, float halfSize) {
  float step = 2.0f * halfSize / float(size);
  return {-halfSize + (float(px) + 0.5f) * step, halfSize - (float(py) + 0.5f) * step};
}

// The C++ equation for a world-space point and normal, in the eye space the
// shaders light in (lights moved there by the same lightInView makeFrameData uses).
glm::vec3 expectedColour(const Scene& scene, glm::vec3 worldPosition, glm::vec3 worldNormal,
                         const Material& material, bool blinn) {
  glm::mat4 view = scene.camera.viewMatrix();
  std::vector<Light> lights;
  for (const Light& light : scene.lights) lights.push_back(lightInView(light, view));
  glm::vec3 position = glm::vec3(view * glm::vec4(worldPosition, 1.0f));
  glm::vec3 normal = glm::mat3(view) * worldNormal;  // the view is rigid
  return illuminate(scene.ambient, lights, position, normal, material, blinn);
}

// Eight lights of both kinds with coloured intensities and attenuation, and a
// material with different k per channel: the whole equation at once.
void addEightLights(Scene& scene) {
  scene.ambient = {0.20f, 0.25f, 0.30f};
  scene.lights = {
      {LightType::Point, {0.6f, 0.4f, 1.5f}, {}, {0.50f, 0.40f, 0.30f}, {1.0f, 0.10f, 0.05f}},
      {LightType::Point, {-0.8f, 0.5f, 1.0f}, {}, {0.10f, 0.20f, 0.35f}, {0.5f, 0.20f, 0.10f}},
      {LightType::Point, {0.2f, -0.9f, 0.8f}, {}, {0.20f, 0.10f, 0.05f}, {1.0f, 0.00f, 0.30f}},
      {LightType::Point, {0.0f, 0.0f, -2.0f}, {}, {0.90f, 0.90f, 0.90f}, {1.0f, 0.00f, 0.00f}},
      {LightType::Directional,
       {},
       {-0.3f, -0.2f, -1.0f},
       {0.15f, 0.10f, 0.10f},
       {1.0f, 0.0f, 0.0f}},
      {LightType::Directional, {}, {0.5f, 0.3f, -0.6f}, {0.05f, 0.12f, 0.08f}, {1.0f, 0.0f, 0.0f}},
      {LightType::Directional, {}, {0.0f, 0.0f, 1.0f}, {0.90f, 0.00f, 0.00f}, {1.0f, 0.0f, 0.0f}},
      {LightType::Point, {-0.3f, 0.7f, 0.4f}, {}, {0.08f, 0.08f, 0.12f}, {1.0f, 0.50f, 0.00f}},
  };
  ASSERT_EQ(scene.lights.size(), size_t(MAX_LIGHTS));
}

// A 3x3-vertex grid in the z = 0 plane whose centre vertex sits exactly on
// the centre of pixel (32, 31) of a 64x64 render with halfSize 1, and whose
// vertex normals lean outwards (normalize(x, y, 1)) so interpolation matters.
constexpr uint32_t kGridImage = 64;
constexpr float kGridOffset = 1.0f / 64.0f;  // pixel centre 32 is at x = -1 + 32.5 / 32

Mesh leaningGrid() {
  Mesh mesh;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      glm::vec3 p{kGridOffset + 0.5f * float(i - 1), kGridOffset + 0.5f * float(j - 1), 0.0f};
      mesh.vertices.push_back(
          {p, glm::normalize(glm::vec3(p.x, p.y, 1.0f)), glm::vec2(0.0f), glm::vec4(1, 0, 0, 1)});
    }
  for (uint32_t j = 0; j < 2; ++j)
    for (uint32_t i = 0; i < 2; ++i) {
      uint32_t a = j * 3 + i, b = a + 1, c = a + 4, d = a + 3;  // counter-clockwise seen from +z
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  return mesh;
}

Scene gridScene(const Material& material) {
  Scene scene;
  scene.name = "grid";
  scene.camera = orthoCameraDownZ(1.0f);
  scene.objects.push_back({"grid", scene.addMesh(leaningGrid()), glm::mat4(1.0f), material});
  return scene;
}

const Material kGridMaterial{
    {0.30f, 0.20f, 0.10f}, {0.50f, 0.35f, 0.20f}, {0.30f, 0.40f, 0.25f}, 20.0f};

// Per mode, the GPU colour at a vertex (flat: inside a triangle, whose one
// colour is the equation at the centroid) equals the C++ equation with all
// eight lights, within 1/255 per channel.
class EquationAgreement : public ShadingStability,
                          public ::testing::WithParamInterface<ShadingModel> {};

TEST_P(EquationAgreement, GpuColourMatchesCppEquationWithinOneLevel) {
  ShadingModel model = GetParam();
  Scene scene = gridScene(kGridMaterial);
  addEightLights(scene);
  ImageRgba image = renderer().renderToImage(scene, {kGridImage, kGridImage, model}).image;
  bool blinn = model == ShadingModel::BlinnPhong;

  glm::vec3 expected, actual;
  if (model == ShadingModel::Flat) {
    // Triangle (a, b, c) = vertices 4, 5, 8 of the grid: centroid lit with the face normal.
    const Mesh& mesh = scene.meshes[0];
    glm::vec3 a = mesh.vertices[4].position, b = mesh.vertices[5].position,
              c = mesh.vertices[8].position;
    glm::vec3 centroid = (a + b + c) / 3.0f;
    expected = expectedColour(scene, centroid, glm::cross(b - a, c - a), kGridMaterial, false);
    // Pixel (46, 25) lies inside that triangle (x = 0.45, y = 0.20).
    actual = glm::vec3(image.at(46, 25));
  } else {
    glm::vec3 vertex{kGridOffset, kGridOffset, 0.0f};
    ASSERT_EQ(pixelCentre(32, 31, kGridImage, 1.0f), glm::vec2(vertex));
    expected = expectedColour(scene, vertex, glm::normalize(glm::vec3(vertex.x, vertex.y, 1.0f)),
                              kGridMaterial, blinn);
    actual = glm::vec3(image.at(32, 31));
  }
  std::printf("%s: expected (%.4f %.4f %.4f) gpu (%.4f %.4f %.4f)\n",
              std::string(shadingModelName(model)).c_str(), expected.r, expected.g, expected.b,
              actual.r, actual.g, actual.b);
  EXPECT_LE(largestChannelError(expected, actual), kOneLevel);
  // The comparison is sharp: dropping one light moves the colour by more than a level.
  Scene fewer = scene;
  fewer.lights.pop_back();
  glm::vec3 vertex{kGridOffset, kGridOffset, 0.0f};
  EXPECT_GT(largestChannelError(
                expectedColour(scene, vertex, glm::normalize(glm::vec3(vertex.x, vertex.y, 1.0f)),
                               kGridMaterial, blinn),
                expectedColour(fewer, vertex, glm::normalize(glm::vec3(vertex.x, vertex.y, 1.0f)),
                               kGridMaterial, blinn)),
            kOneLevel);
}

INSTANTIATE_TEST_SUITE_P(LitModels, EquationAgreement, ::testing::ValuesIn(kLitModels),
                         [](const auto& info) {
                           std::string name(shadingModelName(info.param));
                           std::erase(name, '-');
                           return name;
                         });

// Gouraud evaluates the equation only at the vertices, so a highlight inside
// one large triangle is lost; subdividing the plane brings it back.
TEST_F(ShadingStability, GouraudLosesTheHighlightUntilThePlaneIsSubdivided) {
  float phongPeak = measureHighlight(renderer(), 1, 320, 180).phongPeak;
  uint32_t recovered = 0;
  for (uint32_t quads : {1u, 2u, 4u, 8u, 16u, 32u, 64u}) {
    HighlightMeasurement m = measureHighlight(renderer(), quads, 320, 180);
    float peak = m.gouraudPeak, phongHere = m.phongPeak;
    std::printf("highlight %2ux%-2u quads: Gouraud peak %.3f, Phong peak %.3f (%.0f%%)\n", quads,
                quads, peak, phongHere, 100.0f * peak / phongHere);
    // Phong does not depend on the tessellation of a plane.
    EXPECT_NEAR(phongHere, phongPeak, 0.01f * phongPeak);
    if (quads == 1) {
      EXPECT_LT(peak, 0.5f * phongPeak) << "Gouraud should lose the highlight";
    }
    if (!recovered && peak >= 0.95f * phongPeak) recovered = quads;
  }
  // Measured on lavapipe: 32x32 quads (2048 triangles) is the first power of
  // two whose Gouraud peak is within 5% of Phong's (96%); 8x8 and 16x16 reach 75%.
  EXPECT_EQ(recovered, 32u);
}

// A coarse icosphere seen in perspective; triangles projected on the CPU.
Scene coarseSphere(uint32_t level) {
  Scene scene;
  scene.name = "icosphere";
  scene.camera.eye = {0.4f, 0.6f, 3.2f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.camera.fovyDegrees = 45.0f;
  scene.ambient = glm::vec3(0.15f);
  scene.lights.push_back({LightType::Point, {2.0f, 3.0f, 3.0f}, {}, glm::vec3(1.0f), {1, 0, 0}});
  scene.objects.push_back({"ball",
                           scene.addMesh(makeIcosphere(1.0f, level)),
                           glm::mat4(1.0f),
                           {glm::vec3(0.1f), {0.6f, 0.5f, 0.4f}, glm::vec3(0.4f), 24.0f}});
  return scene;
}

struct FacetCheck {
  uint32_t trianglesChecked = 0;  // front-facing with at least 4 interior pixels
  uint32_t trianglesVarying = 0;  // of those, with more than one distinct colour inside
};

// Every pixel whose centre lies at least 1.5 pixels inside a front-facing
// triangle (the sphere is convex, so front faces are visible).
FacetCheck checkFacets(const Scene& scene, const ImageRgba& image) {
  float aspect = float(image.width) / float(image.height);
  glm::mat4 viewProjection = scene.camera.projectionMatrix(aspect) * scene.camera.viewMatrix();
  const Mesh& mesh = scene.meshes[0];
  FacetCheck check;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    glm::vec3 world[3];
    glm::vec2 screen[3];
    for (int k = 0; k < 3; ++k) {
      world[k] = mesh.vertices[mesh.indices[t + k]].position;
      glm::vec4 clip = viewProjection * glm::vec4(world[k], 1.0f);
      glm::vec2 ndc = glm::vec2(clip) / clip.w;
      screen[k] = {(ndc.x * 0.5f + 0.5f) * float(image.width),
                   (ndc.y * 0.5f + 0.5f) * float(image.height)};
    }
    glm::vec3 normal = glm::cross(world[1] - world[0], world[2] - world[0]);
    if (glm::dot(normal, scene.camera.eye - world[0]) <= 0.0f) continue;
    float area = (screen[1].x - screen[0].x) * (screen[2].y - screen[0].y) -
                 (screen[2].x - screen[0].x) * (screen[1].y - screen[0].y);
    glm::vec2 lo = glm::min(screen[0], glm::min(screen[1], screen[2]));
    glm::vec2 hi = glm::max(screen[0], glm::max(screen[1], screen[2]));
    std::set<std::tuple<float, float, float>> colours;
    uint32_t inside = 0;
    for (int y = std::max(0, int(lo.y)); y <= std::min(int(image.height) - 1, int(hi.y)); ++y)
      for (int x = std::max(0, int(lo.x)); x <= std::min(int(image.width) - 1, int(hi.x)); ++x) {
        glm::vec2 p{float(x) + 0.5f, float(y) + 0.5f};
        bool interior = true;
        for (int k = 0; k < 3; ++k) {
          glm::vec2 a = screen[k], b = screen[(k + 1) % 3];
          float edge = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
          // Signed distance from the edge, positive inside whatever the winding.
          float distance = (area > 0.0f ? edge : -edge) / glm::length(b - a);
          interior = interior && distance >= 1.5f;
        }
        if (!interior) continue;
        ++inside;
        glm::vec4 c = image.at(uint32_t(x), uint32_t(y));
        colours.insert({c.r, c.g, c.b});
      }
    if (inside < 4) continue;
    ++check.trianglesChecked;
    check.trianglesVarying += colours.size() > 1;
  }
  return check;
}

TEST_F(ShadingStability, FlatGivesEachTriangleExactlyOneColour) {
  Scene scene = coarseSphere(1);  // 80 triangles
  FacetCheck flat =
      checkFacets(scene, renderer().renderToImage(scene, {480, 360, ShadingModel::Flat}).image);
  std::printf("flat: %u triangles checked, %u with more than one colour\n", flat.trianglesChecked,
              flat.trianglesVarying);
  // About half of the 80 face the camera; those seen nearly edge-on have no
  // interior pixels. 29 are checked at this size.
  EXPECT_GE(flat.trianglesChecked, 25u);
  EXPECT_EQ(flat.trianglesVarying, 0u);
  // The check can fail: Gouraud's interpolated colours vary inside triangles.
  FacetCheck gouraud =
      checkFacets(scene, renderer().renderToImage(scene, {480, 360, ShadingModel::Gouraud}).image);
  EXPECT_GE(gouraud.trianglesVarying, gouraud.trianglesChecked / 2);
}

TEST_F(ShadingStability, FacetingErrorFallsAsTessellationRises) {
  RenderSettings size{320, 240, ShadingModel::Phong};
  ImageU8 reference = encodeSrgb8(renderer().renderToImage(coarseSphere(6), size).image);
  double previous = 1e9;
  double first = 0.0;
  for (uint32_t level = 1; level <= 4; ++level) {
    RenderSettings flat = size;
    flat.shadingModel = ShadingModel::Flat;
    double rmse =
        compareImages(reference,
                      encodeSrgb8(renderer().renderToImage(coarseSphere(level), flat).image))
            .rmse;
    std::printf("flat icosphere level %u (%5u triangles): RMSE %.3f against Phong level 6\n", level,
                20u << (2 * level), rmse);
    EXPECT_LT(rmse, previous) << "level " << level;
    if (level == 1) first = rmse;
    previous = rmse;
  }
  EXPECT_LT(previous, 0.5 * first) << "three levels of subdivision should halve the error";
}

// A tilted plane under a non-uniform scale: lighting matches the C++
// equation with the true normal (from the cross product of transformed
// edges, not from any normal matrix) only when normals go through the
// inverse transpose.
TEST_F(ShadingStability, NonUniformScaleNeedsTheInverseTranspose) {
  constexpr uint32_t kSize = 128;
  constexpr float kHalf = 2.0f;
  Scene scene;
  scene.name = "scaled-plane";
  scene.camera = orthoCameraDownZ(kHalf);
  scene.ambient = glm::vec3(0.1f);
  scene.lights.push_back({LightType::Point, {1.5f, 1.0f, 4.0f}, {}, glm::vec3(1.0f), {1, 0, 0}});
  Material material{glm::vec3(0.1f), {0.6f, 0.6f, 0.6f}, glm::vec3(0.3f), 8.0f};
  // makePlane lies in XZ with normal +Y: stand it up to face +z, tilt it 50
  // degrees about y, then stretch x by 3.
  glm::mat4 model =
      scaling({3.0f, 1.0f, 1.0f}) * rotationY(glm::radians(50.0f)) * rotationX(glm::radians(90.0f));
  scene.objects.push_back({"plane", scene.addMesh(makePlane(2.0f, 4)), model, material});
  glm::vec3 origin = glm::vec3(model * glm::vec4(0, 0, 0, 1));
  glm::vec3 trueNormal = glm::normalize(glm::cross(glm::vec3(model * glm::vec4(1, 0, 0, 0)),
                                                   glm::vec3(model * glm::vec4(0, 0, -1, 0))));
  ASSERT_GT(trueNormal.z, 0.0f);

  auto worstError = [&](NormalTransform normals) {
    RenderSettings settings{kSize, kSize, ShadingModel::Phong};
    settings.normalTransform = normals;
    ImageRgba image = renderer().renderToImage(scene, settings).image;
    float worst = 0.0f;
    for (uint32_t px : {40u, 64u, 88u})
      for (uint32_t py : {40u, 64u, 88u}) {
        glm::vec2 xy = pixelCentre(px, py, kSize, kHalf);
        // Where the view ray (straight down -z) meets the plane.
        float z = origin.z - (trueNormal.x * (xy.x - origin.x) + trueNormal.y * (xy.y - origin.y)) /
                                 trueNormal.z;
        glm::vec3 expected = expectedColour(scene, {xy.x, xy.y, z}, trueNormal, material, false);
        worst = std::max(worst, largestChannelError(expected, glm::vec3(image.at(px, py))));
      }
    return worst;
  };
  float correct = worstError(NormalTransform::InverseTranspose);
  float wrong = worstError(NormalTransform::ModelView);
  std::printf(
      "non-uniform scale: worst error %.4f with the inverse transpose, %.4f with the "
      "model-view matrix\n",
      correct, wrong);
  EXPECT_LE(correct, kOneLevel);
  EXPECT_GT(wrong, 20.0f * kOneLevel);
}

uint64_t nonFinitePixels(const ImageRgba& image) {
  uint64_t count = 0;
  for (float v : image.pixels) count += !std::isfinite(v);
  return count;
}

// Inputs that break naive shaders: a light behind the surface, a light
// exactly on it, shininess 0 and 1000, zero-length and NaN normals.
TEST_F(ShadingStability, DegenerateInputsGiveNoNaNOrInf) {
  Scene scene;
  scene.name = "degenerate";
  scene.camera = orthoCameraDownZ(2.0f);
  scene.ambient = glm::vec3(0.2f);
  // Light 0 sits exactly on the corner vertex (-1, 0.2, 0) of the left quad.
  scene.lights.push_back({LightType::Point, {-1.0f, 0.2f, 0.0f}, {}, glm::vec3(0.8f), {1, 0, 0}});
  // Light 1 is behind every surface (they all face +z).
  scene.lights.push_back({LightType::Point, {0.0f, 0.0f, -5.0f}, {}, glm::vec3(1.0f), {1, 0, 0}});
  Material matte{glm::vec3(0.5f), glm::vec3(0.6f), glm::vec3(0.4f), 32.0f};
  glm::mat4 standUp = rotationX(glm::radians(90.0f));  // plane normal +Y -> +Z

  // Left: a quad touching light 0. Right top/bottom: shininess 0 and 1000.
  Mesh quad = makePlane(0.8f, 2);
  scene.objects.push_back(
      {"touching", scene.addMesh(quad), translation({-1.4f, 0.6f, 0.0f}) * standUp, matte});
  Material dull = matte, sharp = matte;
  dull.shininess = 0.0f;
  sharp.shininess = 1000.0f;
  uint32_t sphere = scene.addMesh(makeUvSphere(0.4f, 16, 8));
  scene.objects.push_back({"shininess 0", sphere, translation({0.9f, 0.9f, 0.0f}), dull});
  scene.objects.push_back({"shininess 1000", sphere, translation({0.9f, -0.9f, 0.0f}), sharp});
  // Bottom left: a grid whose normals are zero-length or NaN at some vertices.
  Mesh broken = makePlane(0.8f, 4);
  for (size_t i = 0; i < broken.vertices.size(); ++i) {
    if (i % 3 == 0) broken.vertices[i].normal = glm::vec3(0.0f);
    if (i % 3 == 1) broken.vertices[i].normal = glm::vec3(std::nanf(""));
  }
  scene.objects.push_back({"broken normals", scene.addMesh(broken),
                           translation({-0.9f, -0.9f, 0.0f}) * standUp, matte});
  // Below it all, a plane lit only from behind: exactly the ambient term.
  scene.objects.push_back({"back-lit", scene.addMesh(makePlane(4.0f, 1)),
                           translation({0.0f, 0.0f, -1.0f}) * standUp, matte});

  Scene backLitOnly = scene;
  backLitOnly.lights.erase(backLitOnly.lights.begin());
  for (ShadingModel model : kLitModels) {
    ImageRgba image = renderer().renderToImage(scene, {128, 128, model}).image;
    EXPECT_EQ(nonFinitePixels(image), 0u) << shadingModelName(model);
    // With only the light behind, the back-lit plane is exactly Ia ka.
    ImageRgba behind = renderer().renderToImage(backLitOnly, {128, 128, model}).image;
    EXPECT_EQ(nonFinitePixels(behind), 0u) << shadingModelName(model);
    for (auto [px, py] : {std::pair{64u, 64u}, {64u, 4u}, {4u, 64u}, {124u, 64u}})
      EXPECT_LE(largestChannelError(glm::vec3(behind.at(px, py)), scene.ambient * matte.ka),
                kOneLevel)
          << shadingModelName(model) << " at pixel " << px << "," << py;
  }
}

}  // namespace
}  // namespace shadelab::test
