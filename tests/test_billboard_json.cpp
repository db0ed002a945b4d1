// Billboards and "instances" in the scene format: what each placement makes,
// the scatter's determinism, and the sphere test per-instance culling uses.
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/scene/frustum.h"
#include "core/scene/scene_json.h"

namespace shadelab {
namespace {

Scene withBillboard(const std::string& fields) {
  return parseSceneJson(
      R"({"materials": {"t": {"diffuse_map": {"procedural": "tree", "size": 8}}},
          "objects": [{"shape": "billboard", "material": "t", )" +
          fields + "}]}",
      "b.json");
}

TEST(BillboardJson, DefaultsAreOneCentredSphericalCutOut) {
  Scene scene = withBillboard(R"("transform": [{"translate": [1, 2, 3]}])");
  ASSERT_EQ(scene.billboards.size(), 1u);
  const Billboard& billboard = scene.billboards[0];
  EXPECT_EQ(billboard.kind, BillboardKind::Spherical);
  EXPECT_EQ(billboard.anchor, BillboardAnchor::Center);
  EXPECT_EQ(billboard.alpha, BillboardAlpha::Test);
  EXPECT_EQ(billboard.material.alphaCutoff, 0.5f);
  ASSERT_EQ(billboard.instances.size(), 1u);
  EXPECT_EQ(glm::vec3(billboard.instances[0][3]), glm::vec3(1, 2, 3));
  EXPECT_TRUE(scene.objects.empty());
}

TEST(BillboardJson, GridIsCentredOnTheObject) {
  Scene scene = withBillboard(
      R"("kind": "cylindrical", "axis": [0, 2, 0], "instances": {"grid": {"count": [3, 1, 2], "spacing": [2, 1, 4]}},
         "transform": [{"translate": [10, 0, 0]}])");
  const Billboard& billboard = scene.billboards[0];
  EXPECT_EQ(billboard.axis, glm::vec3(0, 1, 0));
  ASSERT_EQ(billboard.instances.size(), 6u);
  EXPECT_EQ(glm::vec3(billboard.instances[0][3]), glm::vec3(8, 0, -2));
  EXPECT_EQ(glm::vec3(billboard.instances[5][3]), glm::vec3(12, 0, 2));
}

TEST(BillboardJson, ScatterIsSeededAndStaysInItsRectangle) {
  auto scatter = [](int seed) {
    return withBillboard(R"("instances": {"scatter": {"count": 500, "seed": )" +
                         std::to_string(seed) + R"(, "rectangle": [4, 2], "scale": [0.5, 2]}})")
        .billboards[0]
        .instances;
  };
  std::vector<glm::mat4> a = scatter(7), b = scatter(7), c = scatter(8);
  ASSERT_EQ(a.size(), 500u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  for (const glm::mat4& m : a) {
    EXPECT_LE(std::abs(m[3].x), 2.0f);
    EXPECT_LE(std::abs(m[3].z), 1.0f);
    EXPECT_EQ(m[3].y, 0.0f);
    EXPECT_GE(m[0][0], 0.5f);
    EXPECT_LE(m[0][0], 2.0f);
  }
}

// "yaw" turns each copy about y without moving it: its angle is drawn after
// the position and scale, so the same seed places the copies as before.
TEST(BillboardJson, ScatterYawTurnsCopiesInPlace) {
  auto scatter = [](const std::string& yaw) {
    return withBillboard(
               R"("instances": {"scatter": {"count": 50, "seed": 3, "rectangle": [4, 2])" + yaw +
               "}}")
        .billboards[0]
        .instances;
  };
  std::vector<glm::mat4> plain = scatter(""), turned = scatter(R"(, "yaw": [90, 90])");
  ASSERT_EQ(turned.size(), plain.size());
  for (size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(turned[i][3], plain[i][3]);
    // x turns to -z: 90 degrees counter-clockwise about y.
    EXPECT_NEAR(turned[i][0].z, -1.0f, 1e-6f);
    EXPECT_NEAR(turned[i][0].x, 0.0f, 1e-6f);
  }
  EXPECT_THROW(scatter(R"(, "yaw": [10, 5])"), InputError);
  EXPECT_THROW(scatter(R"(, "yaw": [0, 400])"), InputError);
}

TEST(BillboardJson, ListTakesOneTransformEach) {
  Scene scene = withBillboard(
      R"("alpha": "blend", "instances": {"list": [[{"translate": [1, 0, 0]}], [{"scale": [2, 3, 1]}]]})");
  const Billboard& billboard = scene.billboards[0];
  EXPECT_EQ(billboard.alpha, BillboardAlpha::Blend);
  ASSERT_EQ(billboard.instances.size(), 2u);
  EXPECT_EQ(billboard.instances[1][1][1], 3.0f);
}

TEST(BillboardJson, ErrorsNameTheField) {
  auto message = [](const std::string& fields) {
    try {
      withBillboard(fields);
    } catch (const std::exception& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(R"("kind": "round")").find("b.json: objects[0].kind: "), std::string::npos);
  EXPECT_NE(message(R"("instances": {"grid": {"count": [1, 1, 1]}, "list": []})")
                .find("objects[0].instances: it has 2 kinds of placement"),
            std::string::npos);
  EXPECT_NE(message(R"("casts_shadows": true)").find("objects[0]"), std::string::npos);
}

TEST(BillboardJson, SphereCullingAgainstTheFrustum) {
  glm::mat4 projection = glm::mat4(1.0f);  // clip space = the source space: -1..1, 0..1 deep
  Frustum frustum = frustumFromMatrix(projection);
  EXPECT_TRUE(sphereIntersectsFrustum({0, 0, 0.5f}, 0.1f, frustum));
  EXPECT_TRUE(sphereIntersectsFrustum({1.05f, 0, 0.5f}, 0.1f, frustum));  // overlaps x = 1
  EXPECT_FALSE(sphereIntersectsFrustum({1.2f, 0, 0.5f}, 0.1f, frustum));
  EXPECT_FALSE(sphereIntersectsFrustum({0, 0, -0.2f}, 0.1f, frustum));  // before the near plane
}

}  // namespace
}  // namespace shadelab
