// The light views of shadow maps without a device: a point light's cube
// face coordinates found without the face's matrix (what the forward
// pass's fragment stage does, shaders/shadows.glsl) against the matrix the
// shadow pass draws the face with.
#include <gtest/gtest.h>

#include <random>

#include "core/scene/shadows.h"

namespace shadelab {
namespace {

Bounds sceneBox() {
  return Bounds{{-6.0f, -1.0f, -6.0f}, {6.0f, 4.0f, 6.0f}};
}

TEST(ShadowViews, CubeFaceCoordinatesMatchTheFaceMatrices) {
  Light light;
  light.type = LightType::Point;
  light.position = {3.0f, 5.0f, 4.0f};
  ShadowView view = pointShadowView(light, sceneBox(), 2048, 4.0f);
  ASSERT_EQ(view.viewProjection.size(), 6u);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
  float worstXy = 0.0f, worstDepth = 0.0f;
  int perFace[6] = {};
  for (int i = 0; i < 20000; ++i) {
    glm::vec3 v(coordinate(random), coordinate(random), coordinate(random));
    if (glm::length(v) < 0.5f) continue;
    CubeMapPoint point = cubeFaceCoordinates(v, view.cube);
    ASSERT_EQ(point.face, cubeFace(v));
    ++perFace[point.face];
    glm::vec4 clip = view.viewProjection[size_t(point.face)] * glm::vec4(light.position + v, 1.0f);
    glm::vec3 ndc = glm::vec3(clip) / clip.w;
    worstXy = std::max({worstXy, std::abs(ndc.x - point.ndc.x), std::abs(ndc.y - point.ndc.y)});
    worstDepth = std::max(worstDepth, std::abs(ndc.z - point.ndc.z));
    // The major axis lands inside its face (the margin widens each face a little).
    EXPECT_LE(std::abs(point.ndc.x), 1.0f);
    EXPECT_LE(std::abs(point.ndc.y), 1.0f);
  }
  for (int face = 0; face < 6; ++face) EXPECT_GT(perFace[face], 2000) << "face " << face;
  // A texel of a 2048 map is 2 / 2048 = 1e-3 in clip xy: the two agree to
  // well under a hundredth of it; depth to float rounding.
  EXPECT_LT(worstXy, 1e-5f);
  EXPECT_LT(worstDepth, 1e-5f);
  std::printf("cube faces: worst clip xy %.2g, depth %.2g\n", worstXy, worstDepth);
}

// Must-fail twin: faces with (right, up) of the wrong face (+x's for -x)
// are off by whole faces, so the comparison above would catch a slip.
TEST(ShadowViews, ComparisonCatchesAMirroredFace) {
  Light light;
  light.type = LightType::Point;
  light.position = {0.0f, 0.0f, 0.0f};
  ShadowView view = pointShadowView(light, sceneBox(), 2048, 4.0f);
  glm::vec3 v(-4.0f, 1.0f, 2.0f);  // -x face
  CubeMapPoint point = cubeFaceCoordinates(v, view.cube);
  ASSERT_EQ(point.face, 1);
  glm::vec4 wrong = view.viewProjection[0] * glm::vec4(glm::vec3(4.0f, 1.0f, 2.0f), 1.0f);
  EXPECT_GT(std::abs(wrong.x / wrong.w - point.ndc.x), 0.5f);
}

}  // namespace
}  // namespace shadelab
