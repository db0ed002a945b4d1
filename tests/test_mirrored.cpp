// Mirroring transforms (a negative determinant: a scale of -1 along one
// axis) turn a mesh's triangles clockwise. The loaders then give the object
// a mesh wound the other way (reverseWinding, ShapeDesc::mirrored), so back-
// face culling, flat shading's face normals and the ray tracer's outward
// normals all still see the outside. The check is a symmetry: a scene that
// is its own mirror image across x = 0 except for one teapot, drawn once as
// it is and once inside a group scaled by -1 in x, must give the image
// flipped left to right, in every model (with its shadow) and in the ray
// tracer. Each has a must-fail twin: the mirrored teapot with its winding
// turned back, as it was drawn before (inside out, dark), which the
// comparison must reject.
// (Before, the rasteriser drew mirrored shapes inside out and the tracer
// mirrored glTF meshes, whose loader already wound them for the mirror.)
#include <string>

#include "core/metrics/metrics.h"
#include "core/scene/mesh.h"
#include "core/scene/scene_json.h"
#include "core/trace/raytracer.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 160;
constexpr uint32_t kHeight = 120;

// The camera, the light and the ground are symmetric across x = 0; the
// teapot, turned 30 degrees, is not. `mirrored` puts it inside a group
// scaled by -1 in x: the whole scene's mirror image.
Scene teapotScene(bool mirrored) {
  std::string teapot = R"({"name": "teapot", "shape": "teapot", "tessellation": 6,
      "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 30}}],
      "material": {"ka": [0.16, 0.04, 0.03], "kd": [0.8, 0.4, 0.3], "ks": 0.4, "shininess": 40}})";
  if (mirrored)
    teapot =
        R"({"name": "mirror", "transform": [{"scale": [-1, 1, 1]}], "children": [)" + teapot + "]}";
  return parseSceneJson(R"({
    "camera": {"eye": [0, 3, 7], "at": [0, 0.8, 0], "fovy": 45},
    "ambient": 0.3, "background": [0.6, 0.7, 0.9],
    "lights": [{"type": "directional", "direction": [0, -1, -0.6], "intensity": 0.9,
                "shadows": true}],
    "objects": [{"name": "ground", "shape": "plane", "size": 20,
                 "material": {"kd": [0.5, 0.6, 0.4], "ks": 0}}, )" +
                            teapot + "]}",
                        mirrored ? "mirrored.json" : "teapot.json");
}

// The mirrored scene as it was drawn before the loaders wound mirrored
// meshes for their transform: the teapot's triangles clockwise once placed.
Scene insideOut() {
  Scene scene = teapotScene(true);
  Mesh& mesh = scene.meshes[scene.objects.back().mesh];
  reverseWinding(mesh);
  scene.shapes[scene.objects.back().mesh].mirrored = false;  // the tracer rebuilds from the shape
  return scene;
}

ImageU8 flippedLeftToRight(const ImageU8& image) {
  ImageU8 flipped(image.width, image.height);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) flipped.set(image.width - 1 - x, y, image.at(x, y));
  return flipped;
}

// The golden tolerance (40 dB, at most 0.5% of pixels beyond 4/255). On
// lavapipe the mirrored images are the flipped ones to the bit in flat and
// Phong, and within 1/255 in Gouraud and the tracer; the inside-out teapot
// is 13-16 dB away, a quarter of the pixels beyond 8/255.
constexpr ImageTolerance kMirrorTolerance = kGoldenTolerance;

using Mirrored = GpuTest;

TEST_F(Mirrored, MirroredMeshDrawsTheMirrorImageInEveryModel) {
  Scene mirrored = teapotScene(true);
  ASSERT_TRUE(mirrored.shapes[mirrored.objects.back().mesh].mirrored);
  ASSERT_FALSE(teapotScene(false).shapes.back().mirrored);
  for (ShadingModel model : {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong}) {
    SCOPED_TRACE(shadingModelName(model));
    RenderSettings settings{kWidth, kHeight, model};
    settings.shadows = ShadowMethod::Hard;  // the teapot's shadow mirrors with it
    ImageU8 expected = flippedLeftToRight(
        encodeSrgb8(renderer().renderToImage(teapotScene(false), settings).image));
    EXPECT_TRUE(matchesImage(expected,
                             encodeSrgb8(renderer().renderToImage(mirrored, settings).image),
                             kMirrorTolerance));
    EXPECT_FALSE(matchesImage(expected,
                              encodeSrgb8(renderer().renderToImage(insideOut(), settings).image),
                              kMirrorTolerance));
  }
}

TEST_F(Mirrored, RayTracerSeesTheOutsideOfAMirroredMesh) {
  TraceSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.samplesPerPixel = 1;
  Scene plain = teapotScene(false);
  ImageU8 expected = flippedLeftToRight(encodeSrgb8(RayTracer(plain).render(settings).image));
  Scene mirrored = teapotScene(true);
  EXPECT_TRUE(matchesImage(expected, encodeSrgb8(RayTracer(mirrored).render(settings).image),
                           kMirrorTolerance));
  // A loaded mesh (ShapeKind::Custom), wound for the mirror as the glTF
  // loader winds one: traced from its own triangles, at the scene's
  // tessellation (the shapes above are traced 4x finer).
  Scene loaded = teapotScene(true);
  loaded.objects.back().mesh = loaded.addMesh(loaded.meshes[loaded.objects.back().mesh]);
  ImageU8 expectedCoarse =
      flippedLeftToRight(encodeSrgb8(RayTracer(plain, 1.0f).render(settings).image));
  EXPECT_TRUE(matchesImage(expectedCoarse, encodeSrgb8(RayTracer(loaded).render(settings).image),
                           kMirrorTolerance));
  Scene wrong = insideOut();
  EXPECT_FALSE(matchesImage(expected, encodeSrgb8(RayTracer(wrong).render(settings).image),
                            kMirrorTolerance));
}

}  // namespace
}  // namespace shadelab::test
