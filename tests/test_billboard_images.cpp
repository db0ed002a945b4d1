// Billboards and instancing on the device: a golden per billboard kind (all
// alpha-tested) and for alpha blend, each with a must-fail twin; an
// instanced scene bit-identical to the same billboards drawn one by one;
// per-instance culling that changes no pixel.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "core/metrics/metrics.h"
#include "core/scene/billboard_outline.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/scene_json.h"
#include "core/scene/texture.h"
#include "core/trace/raytracer.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;

RenderSettings small() {
  return {kWidth, kHeight, ShadingModel::Phong};
}

// tests/data/billboards.json with every billboard of `kind`.
Scene billboardScene(BillboardKind kind) {
  Scene scene = loadSceneJson(std::string(SHADELAB_TEST_DATA_DIR) + "/billboards.json");
  for (Billboard& billboard : scene.billboards) billboard.kind = kind;
  return scene;
}

// The cylindrical trees blended at 65% opacity, sorted with a translucent box.
Scene blendedScene() {
  Scene scene = billboardScene(BillboardKind::Cylindrical);
  for (Billboard& billboard : scene.billboards) {
    billboard.alpha = BillboardAlpha::Blend;
    billboard.material.transparency = 0.35f;
  }
  scene.objects[1].material.transparency = 0.5f;
  return scene;
}

std::string goldenName(BillboardKind kind) {
  return "billboard-" + std::string(nameOf(kBillboardKindNames, kind));
}

class BillboardGolden : public GpuTest, public ::testing::WithParamInterface<BillboardKind> {};

TEST_P(BillboardGolden, MatchesGolden) {
  EXPECT_TRUE(matchesGolden(goldenName(GetParam()), render(billboardScene(GetParam()), small())));
}

// Must-fail twin: each kind's golden rejects the images of the other two, so
// a pass that turned its quads the wrong way would be caught.
TEST_P(BillboardGolden, RejectsTheOtherKinds) {
  for (BillboardKind other :
       {BillboardKind::Screen, BillboardKind::Spherical, BillboardKind::Cylindrical}) {
    if (other == GetParam()) continue;
    SCOPED_TRACE(nameOf(kBillboardKindNames, other));
    EXPECT_FALSE(
        matchesImage(loadGolden(goldenName(GetParam())), render(billboardScene(other), small())));
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, BillboardGolden,
                         ::testing::Values(BillboardKind::Screen, BillboardKind::Spherical,
                                           BillboardKind::Cylindrical),
                         [](const auto& info) {
                           return std::string(nameOf(kBillboardKindNames, info.param));
                         });

using BillboardImages = GpuTest;

// Must-fail twin of alpha test: with a cut-off of 0 nothing is cut away and
// each tree is its whole quad (black where the texture is transparent).
TEST_F(BillboardImages, AlphaTestComparisonRejectsNoCutOut) {
  Scene scene = billboardScene(BillboardKind::Cylindrical);
  for (Billboard& billboard : scene.billboards) billboard.material.alphaCutoff = 0.0f;
  EXPECT_FALSE(matchesImage(loadGolden("billboard-cylindrical"), render(scene, small())));
}

TEST_F(BillboardImages, AlphaBlendMatchesGolden) {
  EXPECT_TRUE(matchesGolden("billboard-blend", render(blendedScene(), small())));
}

// Must-fail twin: the same trees cut out (opaque) instead of blended.
TEST_F(BillboardImages, AlphaBlendComparisonRejectsOpaqueTrees) {
  Scene scene = blendedScene();
  for (Billboard& billboard : scene.billboards) billboard.material.transparency = 0.0f;
  EXPECT_FALSE(matchesImage(loadGolden("billboard-blend"), render(scene, small())));
}

// Blending is not commutative, so the order must come from depth, not from
// the scene: with the back tree moved to the front of the list the image is
// the same (a pass that drew in list order would draw it last, over the
// trees in front of it).
TEST_F(BillboardImages, BlendedBillboardsAreSortedBackToFront) {
  Scene scene = blendedScene();
  Scene reordered = scene;
  std::vector<glm::mat4>& row = reordered.billboards[0].instances;
  std::rotate(row.rbegin(), row.rbegin() + 1, row.rend());  // the back tree first
  ImageU8 sorted = render(scene, small());
  EXPECT_TRUE(matchesImage(sorted, render(reordered, small()), {99.0, 0, 0.0}));
}

// One billboard object with N instances draws exactly what N billboard
// objects with one placement each draw.
std::string treesJson(const std::string& billboards) {
  return R"({"camera": {"eye": [0, 2.5, 8], "at": [0, 1, 0]},
    "lights": [{"type": "directional", "direction": [-1, -1, -1]}],
    "materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 64}}},
    "objects": [{"shape": "plane", "size": 10}, )" +
         billboards + "]}";
}

std::string oneByOne(float shift) {
  std::string objects;
  const float xs[] = {-3.0f, -1.0f, 1.0f, 3.0f};
  for (int i = 0; i < 4; ++i) {
    float x = xs[i] + (i == 2 ? shift : 0.0f);
    objects +=
        std::string(i ? ", " : "") +
        R"({"shape": "billboard", "kind": "cylindrical", "anchor": "bottom", "size": [1.5, 2], "material": "tree", "transform": [{"translate": [)" +
        std::to_string(x) + R"(, 0, -1]}]})";
  }
  return treesJson(objects);
}

TEST_F(BillboardImages, InstancedEqualsOneByOneBitForBit) {
  Scene instanced = parseSceneJson(
      treesJson(
          R"({"shape": "billboard", "kind": "cylindrical", "anchor": "bottom", "size": [1.5, 2], "material": "tree",
        "instances": {"grid": {"count": [4, 1, 1], "spacing": [2, 1, 1]}},
        "transform": [{"translate": [0, 0, -1]}]})"),
      "instanced.json");
  Scene separate = parseSceneJson(oneByOne(0.0f), "separate.json");
  ASSERT_EQ(instanced.billboards.size(), 1u);
  ASSERT_EQ(separate.billboards.size(), 4u);
  RenderResult a = renderer().renderToImage(instanced, small());
  RenderResult b = renderer().renderToImage(separate, small());
  EXPECT_EQ(a.stats.billboardInstances, 4u);
  EXPECT_EQ(b.stats.billboardInstances, 4u);
  ASSERT_EQ(a.image.pixels.size(), b.image.pixels.size());
  EXPECT_EQ(0, std::memcmp(a.image.pixels.data(), b.image.pixels.data(),
                           a.image.pixels.size() * sizeof(float)));
  // Twin: one tree a hundredth of a unit aside is caught by the same comparison.
  RenderResult moved =
      renderer().renderToImage(parseSceneJson(oneByOne(0.01f), "moved.json"), small());
  EXPECT_NE(0, std::memcmp(a.image.pixels.data(), moved.image.pixels.data(),
                           a.image.pixels.size() * sizeof(float)));
}

// Culling drops instances outside the view (most of the forest behind and
// beside the camera) without changing a pixel.
TEST_F(BillboardImages, InstanceCullingChangesNoPixel) {
  Scene scene = builtinScene("trees");
  scene.camera.at = scene.camera.eye + glm::vec3(1.0f, -0.1f, 0.0f);  // look along +x
  RenderSettings settings = small();
  RenderResult culled = renderer().renderToImage(scene, settings);
  settings.frustumCulling = false;
  RenderResult all = renderer().renderToImage(scene, settings);
  EXPECT_GT(culled.stats.culledInstances, 1000u);
  EXPECT_EQ(all.stats.culledInstances, 0u);
  EXPECT_EQ(culled.stats.billboardInstances + culled.stats.culledInstances,
            all.stats.billboardInstances);
  EXPECT_EQ(0, std::memcmp(culled.image.pixels.data(), all.image.pixels.data(),
                           culled.image.pixels.size() * sizeof(float)));
}

// The forest is one instanced draw, whatever its size.
TEST_F(BillboardImages, ThousandsOfTreesAreOneDraw) {
  Scene scene = builtinScene("trees");
  RenderResult result = renderer().renderToImage(scene, small());
  // The meshes' draws plus one per billboard object (forest, grove).
  EXPECT_LE(result.stats.drawCalls, uint32_t(scene.objects.size()) + 2u);
  EXPECT_GT(result.stats.billboardInstances, 1000u);
}

// The traced reference draws the quads the rasteriser draws (core/scene/
// billboard_quad.h): for each kind cut out, for blended trees and for a
// normal-mapped row, raster Phong against the trace at pixel centres agree
// to a small mean FLIP, with shadows in both. Must-fail twins: the tracer
// without the billboards (what it drew before) and the tracer with the
// quads turned another kind's way are clearly further off.
double traceAgainst(const ImageU8& raster, const Scene& traced) {
  TraceSettings trace;
  trace.width = kWidth, trace.height = kHeight, trace.samplesPerPixel = 1;
  return flipError(encodeSrgb8(RayTracer(traced).render(trace).image), raster).mean;
}

TEST_F(BillboardImages, TracedReferenceDrawsTheSameQuads) {
  Scene bumped = billboardScene(BillboardKind::Cylindrical);
  bumped.textures.push_back(
      normalMapTexture(proceduralHeight({HeightPattern::Bricks, 64, 4}), 8.0f, "bricks"));
  for (Billboard& billboard : bumped.billboards)
    billboard.material.normalMap.texture = int32_t(bumped.textures.size() - 1);
  // The box opaque: the rasteriser blends a transparent one where the tracer refracts.
  Scene blended = blendedScene();
  blended.objects[1].material.transparency = 0.0f;
  const struct {
    const char* name;
    Scene scene;
    BillboardKind otherKind;
  } cases[] = {{"screen", billboardScene(BillboardKind::Screen), BillboardKind::Cylindrical},
               {"spherical", billboardScene(BillboardKind::Spherical), BillboardKind::Screen},
               {"cylindrical", billboardScene(BillboardKind::Cylindrical), BillboardKind::Screen},
               {"blended", blended, BillboardKind::Screen},
               {"normal-mapped", bumped, BillboardKind::Screen}};
  for (const auto& c : cases) {
    const ImageU8 raster = render(c.scene, small());
    const double same = traceAgainst(raster, c.scene);
    Scene without = c.scene;
    without.billboards.clear();
    const double missing = traceAgainst(raster, without);
    Scene turned = c.scene;
    for (Billboard& billboard : turned.billboards) billboard.kind = c.otherKind;
    const double wrong = traceAgainst(raster, turned);
    std::printf(
        "%s billboards, raster Phong vs trace: mean FLIP %.4f; without them %.4f; turned "
        "as %s %.4f\n",
        c.name, same, missing, std::string(nameOf(kBillboardKindNames, c.otherKind)).c_str(),
        wrong);
    EXPECT_LE(same, 0.02) << c.name;
    EXPECT_GT(missing, 2.0 * same + 0.005) << c.name;
    EXPECT_GT(wrong, 1.5 * same + 0.003) << c.name;
  }
}

// A normal map changes how the quads are lit (Phong, per fragment); --bump
// off draws them as without one.
TEST_F(BillboardImages, NormalMapIsAppliedAndBumpOffRemovesIt) {
  Scene plain = billboardScene(BillboardKind::Cylindrical);
  Scene bumped = plain;
  HeightField bricks = proceduralHeight({HeightPattern::Bricks, 64, 4});
  bumped.textures.push_back(normalMapTexture(bricks, 8.0f, "bricks (normal map)"));
  for (Billboard& billboard : bumped.billboards)
    billboard.material.normalMap.texture = int32_t(bumped.textures.size() - 1);
  ImageU8 withMap = render(bumped, small());
  EXPECT_FALSE(matchesImage(render(plain, small()), withMap));
  RenderSettings off = small();
  off.textures.bump = false;
  EXPECT_TRUE(matchesImage(render(plain, small()), render(bumped, off), {99.0, 0, 0.0}));
}

uint64_t treePixels(const ImageU8& image) {
  uint64_t count = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      glm::u8vec4 pixel = image.at(x, y);
      count += pixel.g > pixel.r + 20 && pixel.g > pixel.b + 20;  // the crown's green
    }
  return count;
}

// The cylindrical billboard's known failure, measured: seen along its axis
// (from straight above a tree) the quad is edge-on and all but vanishes,
// where a spherical one still shows the whole tree.
TEST_F(BillboardImages, CylindricalSeenAlongItsAxisIsEdgeOn) {
  Scene scene = parseSceneJson(
      R"({"camera": {"eye": [0, 10, 0], "at": [0, 0, 0], "up": [0, 0, -1]},
          "ambient": 1, "background": [0, 0, 0],
          "materials": {"t": {"diffuse_map": {"procedural": "tree", "size": 64}}},
          "objects": [{"shape": "billboard", "material": "t", "size": [3, 4]}]})",
      "above.json");
  scene.billboards[0].kind = BillboardKind::Spherical;
  uint64_t spherical = treePixels(render(scene, small()));
  scene.billboards[0].kind = BillboardKind::Cylindrical;
  uint64_t cylindrical = treePixels(render(scene, small()));
  EXPECT_GT(spherical, 1000u);  // 2,222 here; the cylindrical quad: 0
  EXPECT_LT(cylindrical * 50, spherical) << "cylindrical " << cylindrical;
}

// Trimmed outlines (core/scene/billboard_outline.h): a triangle around what
// the texture can show at the levels a copy samples draws the quad's pixels.
// Trees float apart (no ground, no two quads meeting, so no depth ties),
// from 0.8 to 100 units away: magnified down to ~1 pixel, every mip level;
// three kinds cut out and one row blended; each texture filter.
std::string floatingTrees(float cutoff) {
  std::string rows;
  const char* kinds[] = {"screen", "spherical", "cylindrical", "cylindrical"};
  const float distances[] = {0.8f, 1.5f, 3.0f, 6.0f, 12.0f, 25.0f, 50.0f, 100.0f};
  for (int row = 0; row < 4; ++row) {
    std::string list;
    for (int i = 0; i < 8; ++i) {
      float d = distances[i] * (1.0f + 0.15f * float(row));
      float x = d * std::tan(0.17f * (float(i) - 3.5f)),
            y = d * std::tan(0.2f * (float(row) - 1.5f));
      list += std::string(list.empty() ? "" : ", ") + "[{\"translate\": [" + std::to_string(x) +
              ", " + std::to_string(y) + ", " + std::to_string(-d) + "]}]";
    }
    rows += std::string(row ? ", " : "") + R"({"shape": "billboard", "kind": ")" + kinds[row] +
            R"(", "size": [0.3, 0.4], "material": "tree", )" +
            (row == 3 ? std::string(R"("alpha": "blend")")
                      : R"("alpha_cutoff": )" + std::to_string(cutoff)) +
            R"(, "instances": {"list": [)" + list + "]}}";
  }
  return R"({"camera": {"eye": [0, 0, 0], "at": [0, 0, -1], "fovy": 50},
    "background": [0.4, 0.55, 0.8],
    "lights": [{"type": "directional", "direction": [-1, -1, -1]}],
    "materials": {"tree": {"ka": 0.4, "kd": 0.8, "ks": 0.3, "shininess": 16,
      "diffuse_map": {"procedural": "tree", "size": 128},
      "sampler": {"wrap_u": "clamp_to_edge", "wrap_v": "clamp_to_edge"}}},
    "objects": [)" +
         rows + "]}";
}

TEST_F(BillboardImages, TrimmedOutlinesDrawTheQuadsPixels) {
  Scene scene = parseSceneJson(floatingTrees(0.5f), "floating.json");
  for (std::optional<TextureFilter> filter :
       {std::optional<TextureFilter>(), std::optional(TextureFilter::Nearest),
        std::optional(TextureFilter::Bilinear), std::optional(TextureFilter::Trilinear)}) {
    SCOPED_TRACE(filter ? textureFilterName(*filter) : "material's");
    RenderSettings settings = small();
    settings.textures.filterOverride = filter;
    RenderResult trimmed = renderer().renderToImage(scene, settings);
    settings.trimBillboards = false;
    RenderResult quads = renderer().renderToImage(scene, settings);
    // The cut-out rows are trimmed at every distance; the blended row where
    // a level's alpha leaves room (its coarsest levels cover the quad).
    uint32_t instances = trimmed.stats.billboardInstances;
    EXPECT_GE(instances, 28u);  // a few nearest copies reach past the view
    EXPECT_GE(trimmed.stats.trimmedInstances, 20u);
    EXPECT_EQ(quads.stats.trimmedInstances, 0u);
    EXPECT_EQ(trimmed.stats.triangles + trimmed.stats.trimmedInstances, quads.stats.triangles);
    // The uv a fragment interpolates from another triangle may round
    // differently: a filtered texel then moves by one RGBA16F step (one
    // 8-bit code at most), never more; a fragment the triangle missed would
    // differ by far more.
    EXPECT_EQ(valuesBeyondOneHalfStep(trimmed.image.pixels, quads.image.pixels), 0u);
    EXPECT_LE(compareImages(encodeSrgb8(trimmed.image), encodeSrgb8(quads.image)).maxDifference, 1);
  }
  // Twin: the cut-out's edge moved (a cut-off of 0.45 instead of 0.5) is
  // caught by the same comparison, as a triangle cutting into it would be.
  RenderResult trimmed = renderer().renderToImage(scene, small());
  RenderSettings settings = small();
  settings.trimBillboards = false;
  RenderResult moved =
      renderer().renderToImage(parseSceneJson(floatingTrees(0.45f), "moved.json"), settings);
  EXPECT_GT(valuesBeyondOneHalfStep(trimmed.image.pixels, moved.image.pixels), 20u);
}

// Multisampled and anisotropic frames draw quads (the header says why).
TEST_F(BillboardImages, MultisampledAndAnisotropicFramesDrawQuads) {
  Scene scene = parseSceneJson(floatingTrees(0.5f), "floating.json");
  RenderSettings settings = small();
  settings.msaaSamples = 4;
  EXPECT_EQ(renderer().renderToImage(scene, settings).stats.trimmedInstances, 0u);
  settings = small();
  settings.textures.filterOverride = TextureFilter::Anisotropic;
  EXPECT_EQ(renderer().renderToImage(scene, settings).stats.trimmedInstances, 0u);
}

// Outlines are computed for at most kMaxOutlineSets (texture, wrap,
// cut-off) sets a scene: 65 billboards of one texture with 65 cut-offs
// trim all but the last.
TEST_F(BillboardImages, OutlinesStopAtTheLimit) {
  std::string objects;
  for (size_t i = 0; i <= kMaxOutlineSets; ++i) {
    float x = -3.9f + 0.6f * float(i % 13), y = -1.2f + 0.6f * float(i / 13);
    objects += std::string(i ? ", " : "") +
               R"({"shape": "billboard", "kind": "screen", "size": [0.5, 0.5], "material": "tree",
                  "alpha_cutoff": )" +
               std::to_string(0.3f + 0.004f * float(i)) + R"(, "transform": [{"translate": [)" +
               std::to_string(x) + ", " + std::to_string(y) + ", -10]}]}";
  }
  Scene scene = parseSceneJson(
      R"({"camera": {"eye": [0, 0, 0], "at": [0, 0, -1], "fovy": 50},
          "materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 64},
            "sampler": {"wrap_u": "clamp_to_edge", "wrap_v": "clamp_to_edge"}}},
          "objects": [)" +
          objects + "]}",
      "many.json");
  RenderResult result = renderer().renderToImage(scene, small());
  EXPECT_EQ(result.stats.billboardInstances, kMaxOutlineSets + 1);
  EXPECT_EQ(result.stats.trimmedInstances, kMaxOutlineSets);
}

}  // namespace
}  // namespace shadelab::test
