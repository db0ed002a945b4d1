// The environment cube on the device: panoramas land on the faces Vulkan's
// cube layout says (read back, and through the hardware's own lookup in the
// skybox), uploaded faces keep their orientation, and no face edge shows a
// seam at any mip level.
#include <cstdlib>
#include <filesystem>

#include "core/scene/environment.h"
#include "environment_test_support.h"
#include "gpu_test_support.h"
#include "passes/environment_builder.h"

namespace shadelab::test {
namespace {

class EnvironmentCubeTest : public GpuTest {
 protected:
  EnvironmentBuilder& builder() {
    static EnvironmentBuilder instance(context());
    return instance;
  }
  std::array<ImageRgba, 6> buildAndRead(const Environment& environment, uint32_t level = 0) {
    EnvironmentCube cube = builder().build(environment);
    return readCubeLevel(context(), cube, level);
  }
};

glm::vec2 texelCentre(uint32_t x, uint32_t y, uint32_t size) {
  return {(float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size)};
}

// Largest angle between each texel's decoded colour and the direction
// `expected(face, st)` gives for it.
float worstAngle(const std::array<ImageRgba, 6>& faces,
                 const std::function<glm::vec3(uint32_t, glm::vec2)>& expected) {
  float worst = 0.0f;
  for (uint32_t face = 0; face < 6; ++face)
    for (uint32_t y = 0; y < faces[face].height; ++y)
      for (uint32_t x = 0; x < faces[face].width; ++x) {
        glm::vec3 want = expected(face, texelCentre(x, y, faces[face].width));
        worst = std::max(worst, angleBetweenDegrees(decodeDirection(faces[face].at(x, y)), want));
      }
  return worst;
}

// Every texel of every face holds the panorama's colour for the direction
// Vulkan's face table assigns to it (layer 0 = +X, ..., s and t per face).
TEST_F(EnvironmentCubeTest, PanoramaLandsOnTheFacesOfVulkansLayout) {
  std::array<ImageRgba, 6> faces = buildAndRead(panoramaOf(512, 256, 64, encodeDirection));
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (uint32_t face = 0; face < 6; ++face) {
    glm::vec4 centre = 0.25f * (faces[face].at(31, 31) + faces[face].at(32, 31) +
                                faces[face].at(31, 32) + faces[face].at(32, 32));
    EXPECT_LT(angleBetweenDegrees(decodeDirection(centre), axes[face]), 1.0f) << "face " << face;
  }
  float worst =
      worstAngle(faces, [](uint32_t face, glm::vec2 st) { return cubeFaceDirection(face, st); });
  EXPECT_LT(worst, 1.5f) << "worst texel " << worst << " degrees off";
  std::printf("panorama -> cube: worst texel %.2f degrees from Vulkan's face table\n", worst);
  // The classic bug, faces seen from outside (s mirrored), is 40+ degrees off.
  float mirrored = worstAngle(faces, [](uint32_t face, glm::vec2 st) {
    return cubeFaceDirection(face, {1.0f - st.x, st.y});
  });
  EXPECT_GT(mirrored, 40.0f);
}

Scene skyboxOnly(const Environment& environment, glm::vec3 forward, float fovy) {
  Scene scene;
  scene.name = "skybox";
  scene.camera.eye = glm::vec3(0.0f);
  scene.camera.at = forward;
  scene.camera.up = std::abs(forward.y) > 0.9f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  scene.camera.fovyDegrees = fovy;
  scene.environment = environment;
  return scene;
}

// Through the hardware's cube lookup: along each axis, every pixel of a
// skybox shows the panorama's colour for its own view ray.
TEST_F(EnvironmentCubeTest, SkyboxShowsEachPixelsViewDirection) {
  Environment environment = panoramaOf(512, 256, 64, encodeDirection);
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (glm::vec3 axis : axes) {
    Scene scene = skyboxOnly(environment, axis, 60.0f);
    ImageRgba image = renderer().renderToImage(scene, {33, 33, ShadingModel::Phong}).image;
    float worst = 0.0f;
    for (uint32_t y = 0; y < 33; y += 4)
      for (uint32_t x = 0; x < 33; x += 4)
        worst = std::max(worst, angleBetweenDegrees(decodeDirection(image.at(x, y)),
                                                    pixelRay(scene.camera, 33, 33, x, y)));
    EXPECT_LT(worst, 1.5f) << "looking along " << axis.x << "," << axis.y << "," << axis.z;
  }
}

// Six uploaded faces: face i is layer i, and (s, t) = (red, green) of a
// face image comes back where Vulkan's table puts it (row 0 = t 0).
TEST_F(EnvironmentCubeTest, UploadedFacesKeepLayerAndOrientation) {
  Environment environment;
  environment.kind = EnvironmentKind::CubeFaces;
  const uint32_t size = 16;
  for (uint32_t face = 0; face < 6; ++face) {
    auto image = std::make_shared<ImageRgba>(size, size);
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x) {
        glm::vec2 st = texelCentre(x, y, size);
        image->set(x, y, {st.x, st.y, float(face) / 5.0f, 1.0f});
      }
    environment.faces[face] = image;
  }
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (uint32_t face = 0; face < 6; ++face) {
    Scene scene = skyboxOnly(environment, axes[face], 50.0f);
    ImageRgba image = renderer().renderToImage(scene, {32, 32, ShadingModel::Phong}).image;
    for (uint32_t y = 4; y < 32; y += 8)
      for (uint32_t x = 4; x < 32; x += 8) {
        CubeCoordinate want = cubeCoordinate(pixelRay(scene.camera, 32, 32, x, y));
        glm::vec4 got = image.at(x, y);
        ASSERT_EQ(want.face, face);
        EXPECT_NEAR(got.b, float(face) / 5.0f, 2e-3f) << "face " << face;
        EXPECT_NEAR(got.r, want.st.x, 0.02f) << "face " << face << " pixel " << x << "," << y;
        EXPECT_NEAR(got.g, want.st.y, 0.02f) << "face " << face << " pixel " << x << "," << y;
      }
  }
}

// Across every edge of every face at every mip level: the jump between the
// texels either side of the edge, against the gradient beside it.
struct SeamMeasure {
  float worstRatio = 0.0f;  // jump / (2 * max neighbouring gradient + 2/1024); > 1 fails
  float meanJump = 0.0f;
  float meanGradient = 0.0f;
};

SeamMeasure measureSeams(const std::array<ImageRgba, 6>& faces) {
  uint32_t n = faces[0].width;
  SeamMeasure measure;
  double jumps = 0.0, gradients = 0.0;
  uint64_t count = 0;
  auto texelAt = [&](glm::vec3 d) {
    CubeCoordinate c = cubeCoordinate(d);
    uint32_t x = std::min(n - 1, uint32_t(c.st.x * float(n)));
    uint32_t y = std::min(n - 1, uint32_t(c.st.y * float(n)));
    return glm::vec3(faces[c.face].at(x, y));
  };
  auto maxChannel = [](glm::vec3 v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  };
  for (uint32_t face = 0; face < 6; ++face)
    for (uint32_t i = 0; i < n; ++i)
      for (int side = 0; side < 4; ++side) {
        // The texel k steps outwards from the edge texel (k = 0), in texel
        // units; k >= 1 lies on the neighbouring face.
        auto stepped = [&](float k) {
          float across = side % 2 == 0 ? 0.5f - k : float(n) - 0.5f + k;
          float inner = float(i) + 0.5f;
          glm::vec2 texel = side < 2 ? glm::vec2(across, inner) : glm::vec2(inner, across);
          return texelAt(cubeFaceDirection(face, texel / float(n)));
        };
        glm::vec3 inside = stepped(-1.0f), edge = stepped(0.0f);
        glm::vec3 beyond = stepped(1.0f), further = stepped(2.0f);
        float jump = maxChannel(beyond - edge);
        float gradient = std::max(maxChannel(edge - inside), maxChannel(further - beyond));
        measure.worstRatio =
            std::max(measure.worstRatio, jump / (2.0f * gradient + 2.0f / 1024.0f));
        jumps += jump, gradients += gradient, ++count;
      }
  measure.meanJump = float(jumps / double(count));
  measure.meanGradient = float(gradients / double(count));
  return measure;
}

TEST_F(EnvironmentCubeTest, NoSeamAtAnyFaceEdgeOrMipLevel) {
  Environment environment = panoramaOf(512, 256, 64, wavyColour);
  EnvironmentCube cube = builder().build(environment);
  ASSERT_EQ(cube.mipLevels(), 7u);
  for (uint32_t level = 0; level + 1 < cube.mipLevels(); ++level) {  // down to 2x2
    SeamMeasure seams = measureSeams(readCubeLevel(context(), cube, level));
    EXPECT_LE(seams.worstRatio, 1.0f) << "level " << level << ": a jump of more than twice the "
                                      << "gradient beside it";
    std::printf(
        "level %u (%ux%u): worst jump / (2 gradient + 2/1024) = %.2f, mean jump %.4f, "
        "mean gradient %.4f\n",
        level, 64u >> level, 64u >> level, seams.worstRatio, seams.meanJump, seams.meanGradient);
  }
}

// Must-fail twin of the seam measure: faces built as if seen from outside
// the cube (s mirrored), the classic conversion bug, must be caught.
TEST_F(EnvironmentCubeTest, SeamMeasureCatchesMirroredFaces) {
  Environment environment;
  environment.kind = EnvironmentKind::CubeFaces;
  const uint32_t size = 32;
  for (uint32_t face = 0; face < 6; ++face) {
    auto image = std::make_shared<ImageRgba>(size, size);
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x) {
        glm::vec2 st = texelCentre(x, y, size);
        glm::vec3 wrong = cubeFaceDirection(face, {1.0f - st.x, st.y});
        image->set(x, y, glm::vec4(wavyColour(wrong), 1.0f));
      }
    environment.faces[face] = image;
  }
  float ratio = measureSeams(buildAndRead(environment)).worstRatio;
  EXPECT_GT(ratio, 3.0f);
  std::printf("mirrored faces, read back: worst ratio %.2f\n", ratio);
}

// The same, measured where a user sees it: a skybox looking straight at the
// edge between +X and -Z (pixel columns 31 | 32), zoomed so a cube texel
// spans ~11 pixels. Bilinear filtering spreads any seam over the one texel
// that straddles the edge, so the steps between neighbouring columns inside
// that band (28..34) are compared with those a texel or more away (8..14,
// 49..55), where each face is filtered on its own.
float skyboxEdgeRatio(const Environment& environment, Renderer& renderer) {
  Scene scene = skyboxOnly(environment, glm::normalize(glm::vec3(1, 0, -1)), 20.0f);
  ImageRgba image = renderer.renderToImage(scene, {64, 64, ShadingModel::Phong}).image;
  float worst = 0.0f;
  auto step = [&](uint32_t x, uint32_t y) {
    glm::vec4 d = image.at(x + 1, y) - image.at(x, y);
    return std::max({std::abs(d.r), std::abs(d.g), std::abs(d.b)});
  };
  for (uint32_t y = 8; y < 56; ++y) {
    float beside = 0.0f, across = 0.0f;
    for (uint32_t x = 8; x <= 14; ++x) beside = std::max({beside, step(x, y), step(x + 41, y)});
    for (uint32_t x = 28; x <= 34; ++x) across = std::max(across, step(x, y));
    worst = std::max(worst, across / (1.5f * beside + 2.0f / 1024.0f));
  }
  return worst;
}

TEST_F(EnvironmentCubeTest, SkyboxShowsNoSeamAcrossAFaceEdge) {
  Environment environment = panoramaOf(256, 128, 16, wavyColour);
  float ratio = skyboxEdgeRatio(environment, renderer());
  EXPECT_LE(ratio, 1.0f) << "a step across the edge exceeds 1.5x the steps beside it";
  std::printf("skybox across the +X/-Z edge: step / (1.5 x neighbouring step + 2/1024) = %.2f\n",
              ratio);
}

TEST_F(EnvironmentCubeTest, SkyboxSeamMeasureCatchesMirroredFaces) {
  Environment environment;
  environment.kind = EnvironmentKind::CubeFaces;
  const uint32_t size = 16;
  for (uint32_t face = 0; face < 6; ++face) {
    auto image = std::make_shared<ImageRgba>(size, size);
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x) {
        glm::vec2 st = texelCentre(x, y, size);
        image->set(x, y, glm::vec4(wavyColour(cubeFaceDirection(face, {1.0f - st.x, st.y})), 1));
      }
    environment.faces[face] = image;
  }
  float ratio = skyboxEdgeRatio(environment, renderer());
  EXPECT_GT(ratio, 2.0f);
  std::printf("mirrored faces, skybox across the edge: ratio %.2f\n", ratio);
}

// Real panoramas (shared assets, skipped when absent): finite everywhere and,
// on average, no bigger step across face edges than beside them.
TEST_F(EnvironmentCubeTest, RealPanoramasConvertWithoutSeams) {
  const char* override = std::getenv("SHADELAB_SHARED_ASSETS");
  std::filesystem::path assets = override ? override : SHADELAB_SHARED_ASSET_DIR;
  std::filesystem::path folder = assets / "environments";
  if (!std::filesystem::exists(folder / "field.jpg"))
    GTEST_SKIP() << folder << " is absent (set SHADELAB_SHARED_ASSETS to the shared assets)";
  for (const char* name : {"field.jpg", "neutral.jpg"}) {
    Environment environment;
    environment.kind = EnvironmentKind::Panorama;
    environment.panorama = std::make_shared<const ImageRgba>(readLinearImage(folder / name));
    std::array<ImageRgba, 6> faces = buildAndRead(environment);
    EXPECT_EQ(faces[0].width, 256u);
    for (const ImageRgba& face : faces)
      for (float value : face.pixels) ASSERT_TRUE(std::isfinite(value)) << name;
    SeamMeasure seams = measureSeams(faces);
    EXPECT_LE(seams.meanJump, 1.5f * seams.meanGradient) << name;
    std::printf("%s: mean step across face edges %.4f, beside them %.4f\n", name, seams.meanJump,
                seams.meanGradient);
  }
}

}  // namespace
}  // namespace shadelab::test
