// The ray tracer's pieces against hand-worked numbers: optics, exact
// intersections (also under non-uniform scale), the BVH against brute force,
// camera rays against the projection matrices, and shading against the C++
// illumination equation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/base/errors.h"
#include "core/scene/billboard_quad.h"
#include "core/scene/lighting.h"
#include "core/scene/texture.h"
#include "core/scene/transform.h"
#include "core/trace/bvh.h"
#include "core/trace/ray.h"
#include "core/trace/raytracer.h"
#include "core/trace/trace_shapes.h"

namespace shadelab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(Optics, MirrorDirectionReflectsAboutTheNormal) {
  glm::vec3 d = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
  expectNear(mirrorDirection(d, {0, 1, 0}), glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)), 1e-6f);
}

TEST(Optics, RefractionObeysSnellsLaw) {
  const float eta = 1.0f / 1.5f;
  for (float degrees : {0.0f, 20.0f, 45.0f, 80.0f}) {
    const float angle = glm::radians(degrees);
    const glm::vec3 d{std::sin(angle), -std::cos(angle), 0.0f};
    std::optional<glm::vec3> t = refractDirection(d, {0, 1, 0}, eta);
    ASSERT_TRUE(t.has_value()) << degrees;
    EXPECT_NEAR(glm::length(*t), 1.0f, 1e-6f);
    // n1 sin(theta1) = n2 sin(theta2), and the ray keeps going down.
    EXPECT_NEAR(1.0f * std::sin(angle), 1.5f * t->x, 1e-6f) << degrees;
    EXPECT_LT(t->y, 0.0f);
  }
}

TEST(Optics, TotalInternalReflectionBeyondTheCriticalAngle) {
  const float critical = std::asin(1.0f / 1.5f);  // 41.8 degrees, glass to air
  const glm::vec3 normal{0, 1, 0};
  auto at = [&](float angle) { return glm::vec3(std::sin(angle), -std::cos(angle), 0.0f); };
  EXPECT_TRUE(refractDirection(at(critical - 0.01f), normal, 1.5f).has_value());
  EXPECT_FALSE(refractDirection(at(critical + 0.01f), normal, 1.5f).has_value());
  EXPECT_FALSE(refractDirection(glm::vec3(std::nanf("")), normal, 1.5f).has_value());
}

TEST(TraceShapes, SphereHitDistanceNormalAndUv) {
  LocalHit hit;
  ASSERT_TRUE(intersectSphere({{0, 0, 5}, {0, 0, -1}}, 1.0f, 0.0f, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 4.0f);
  expectNear(hit.normal, {0, 0, 1}, 1e-6f);
  EXPECT_NEAR(hit.uv.x, 0.5f, 1e-6f);  // the middle of the texture faces +Z
  // From inside, the first crossing ahead is the far wall.
  ASSERT_TRUE(intersectSphere({{0, 0, 0}, {0, 0, -1}}, 2.0f, 0.0f, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 2.0f);
  EXPECT_FALSE(intersectSphere({{0, 1.01f, 5}, {0, 0, -1}}, 1.0f, 0.0f, kInf, hit));
  EXPECT_EQ(countInRange(sphereCrossings({{0, 0, 5}, {0, 0, -1}}, 1.0f), 0.0f, kInf), 2u);
}

TEST(TraceShapes, PlaneIsTheFiniteSquare) {
  LocalHit hit;
  ASSERT_TRUE(intersectPlane({{0.9f, 2, -0.9f}, {0, -1, 0}}, 2.0f, 0.0f, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 2.0f);
  EXPECT_NEAR(hit.uv.x, 0.95f, 1e-6f);  // u along +x, v along -z, as makePlane
  EXPECT_NEAR(hit.uv.y, 0.95f, 1e-6f);
  EXPECT_FALSE(intersectPlane({{1.1f, 2, 0}, {0, -1, 0}}, 2.0f, 0.0f, kInf, hit));
}

TEST(TraceShapes, BoxBySlabsFromOutsideAndInside) {
  LocalHit hit;
  const glm::vec3 half{1.0f, 2.0f, 3.0f};
  ASSERT_TRUE(intersectBox({{5, 0.5f, 0.5f}, {-1, 0, 0}}, half, 0.0f, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 4.0f);
  expectNear(hit.normal, {1, 0, 0}, 0.0f);
  ASSERT_TRUE(intersectBox({{0, 0, 0}, {0, 0, 1}}, half, 0.0f, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 3.0f);  // the exit through +z
  expectNear(hit.normal, {0, 0, 1}, 0.0f);
  EXPECT_FALSE(intersectBox({{5, 2.5f, 0}, {-1, 0, 0}}, half, 0.0f, kInf, hit));
}

// One object on its own: the tracer's hit in world space.
Scene oneObject(ShapeDesc shape, glm::mat4 transform) {
  Scene scene;
  scene.background = {0.1f, 0.2f, 0.3f};
  uint32_t mesh = scene.addShape(shape);
  scene.objects.push_back({"object", mesh, transform, Material{}});
  return scene;
}

TEST(RayTracer, NonUniformScaleIntersectsTheEllipsoidWithItsTrueNormal) {
  ShapeDesc sphere{ShapeKind::UvSphere};
  sphere.radius = 1.0f;
  Scene scene = oneObject(sphere, translation({1, 0, 0}) * scaling({2, 1, 1}));
  RayTracer tracer(scene);
  // x^2/4 + y^2 = 1 (shifted by 1 in x); at x' = sqrt(2), y = sqrt(0.5) the
  // outward normal is along the gradient (x'/4, y) = (0.354, 0.707).
  const float x = std::sqrt(2.0f), y = std::sqrt(0.5f);
  std::optional<SurfaceHit> hit = tracer.intersect({{1 + x, y, 5}, {0, 0, -1}}, 0.0f, kInf);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 5.0f, 1e-5f);
  expectNear(hit->shadingNormal, glm::normalize(glm::vec3(x / 4.0f, y, 0.0f)), 1e-5f);
  EXPECT_TRUE(hit->frontFace);
  hit = tracer.intersect({{5, 0, 0}, {-1, 0, 0}}, 0.0f, kInf);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 2.0f, 1e-5f);  // the surface at x = 1 + 2
}

TEST(RayTracer, RotatedScaledBoxIsIntersectedInObjectSpace) {
  ShapeDesc box{ShapeKind::Box};
  box.halfExtents = glm::vec3(0.5f);
  // Scaled to 2 x 1 x 1 along x, then turned 90 degrees about y: 2 deep in z.
  const Scene scene = oneObject(box, rotationY(glm::radians(90.0f)) * scaling({2, 1, 1}));
  RayTracer tracer(scene);
  std::optional<SurfaceHit> hit = tracer.intersect({{0.2f, 0.1f, 5}, {0, 0, -1}}, 0.0f, kInf);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 4.0f, 1e-5f);
  expectNear(hit->shadingNormal, {0, 0, 1}, 1e-5f);
  EXPECT_FALSE(tracer.intersect({{0.6f, 0.1f, 5}, {0, 0, -1}}, 0.0f, kInf).has_value());
}

// Shadow rays pass transparent surfaces dimmed at each crossing by kt (1 - F),
// Schlick's F at the ray's angle from air: head-on F0 = (0.5 / 2.5)^2 = 0.04
// for ior 1.5; by kt alone without Fresnel.
TEST(RayTracer, GlassCastsALighterShadowThanAnOpaqueBall) {
  ShapeDesc sphere{ShapeKind::UvSphere};
  Scene scene = oneObject(sphere, glm::mat4(1.0f));
  const Ray throughBall{{0, -5, 0}, {0, 1, 0}};
  scene.objects[0].material.transparency = 0.5f;
  scene.objects[0].material.ior = 1.5f;
  EXPECT_FLOAT_EQ(RayTracer(scene).transmittance(throughBall, kInf, false), 0.25f);  // in, out
  EXPECT_NEAR(RayTracer(scene).transmittance(throughBall, kInf), 0.25f * 0.96f * 0.96f, 1e-6f);
  // Off centre the ray meets the ball at 60 degrees both times: cos 0.5.
  const Ray offCentre{{std::sqrt(0.75f), -5, 0}, {0, 1, 0}};
  const float fresnel60 = 0.04f + 0.96f * std::pow(0.5f, 5.0f);
  EXPECT_NEAR(RayTracer(scene).transmittance(offCentre, kInf),
              0.25f * (1.0f - fresnel60) * (1.0f - fresnel60), 1e-5f);
  scene.objects[0].material.transparency = 0.0f;
  EXPECT_EQ(RayTracer(scene).transmittance(throughBall, kInf), 0.0f);
  EXPECT_EQ(RayTracer(scene).transmittance(throughBall, 3.5f), 1.0f);  // ends before the ball
}

// The scene's shadow switches hold for the tracer as for the shadow maps: a
// light with "shadows": false, an object that casts none and one that
// receives none each leave the floor under a box lit. Without them it is
// in the box's shadow (ambient only), which is what each case must differ from.
TEST(RayTracer, ShadowSwitchesOfLightsAndObjectsAreObeyed) {
  ShapeDesc floor{ShapeKind::Plane};
  floor.size = 10.0f;
  Scene scene = oneObject(floor, glm::mat4(1.0f));
  scene.objects[0].material = {{0.2f, 0.2f, 0.2f}, {0.8f, 0.8f, 0.8f}, {0, 0, 0}, 1.0f};
  ShapeDesc box{ShapeKind::Box};
  box.halfExtents = glm::vec3(0.5f);
  scene.objects.push_back(
      {"box", scene.addShape(box), translation({0, 2, 0}), scene.objects[0].material});
  scene.ambient = glm::vec3(0.5f);
  scene.lights = {{LightType::Directional, {}, {0, -1, 0}, glm::vec3(1.0f), {1, 0, 0}}};
  const Ray down{{0.1f, 1.0f, 0.2f}, {0, -1, 0}};  // between box and floor, under the box
  auto shade = [&](const Scene& variant) {
    RayTracer tracer(variant);
    TraceStats stats;
    return tracer.traceRay(down, kInf, glm::vec3(0, 5, 0), 0, 1.0f, TraceSettings{}, stats).g;
  };
  const float shadowed = shade(scene);
  EXPECT_NEAR(shadowed, 0.5f * 0.2f, 1e-5f);  // Ia ka only
  const float lit = 0.5f * 0.2f + 0.8f;       // + Ip kd N.L
  Scene noLightShadows = scene;
  noLightShadows.lights[0].shadows = false;
  EXPECT_NEAR(shade(noLightShadows), lit, 1e-5f);
  Scene boxCastsNone = scene;
  boxCastsNone.objects[1].castsShadows = false;
  EXPECT_NEAR(shade(boxCastsNone), lit, 1e-5f);
  Scene floorReceivesNone = scene;
  floorReceivesNone.objects[0].receivesShadows = false;
  EXPECT_NEAR(shade(floorReceivesNone), lit, 1e-5f);
}

// glTF's alpha blend is coverage: a pane of alpha 0.25 (kt 0.75) shows a
// quarter of its own colour and three quarters of what lies behind, seen
// straight through, as the rasteriser's blend draws it; shadow rays pass
// kt without Fresnel. A scene-file pane of the same kt (Whitted's
// transmission) adds the whole local colour instead.
TEST(RayTracer, CoverageAlphaWeighsTheSurfaceByItsCoverage) {
  ShapeDesc pane{ShapeKind::Plane};
  pane.size = 4.0f;
  Scene scene = oneObject(pane, glm::mat4(1.0f));
  scene.ambient = glm::vec3(0.5f);
  Material& material = scene.objects[0].material;
  material = {glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.0f), 8.0f};
  material.transparency = 0.75f;
  material.ior = 1.0f;
  const Ray down{{0.3f, 2.0f, 0.1f}, {0, -1, 0}};
  auto seen = [&] {
    TraceStats stats;
    return RayTracer(scene).traceRay(down, kInf, down.origin, 0, 1.0f, TraceSettings{}, stats);
  };
  const glm::vec3 behind = scene.background;
  expectNear(seen(), glm::vec3(0.5f) + 0.75f * behind, 1e-5f);  // Whitted
  material.alphaCoverage = true;
  material.ior = 1.5f;  // ignored: coverage does not bend the rays
  expectNear(seen(), 0.25f * glm::vec3(0.5f) + 0.75f * behind, 1e-5f);
  const Ray up{{0.3f, -2.0f, 0.1f}, {0, 1, 0}};
  EXPECT_FLOAT_EQ(RayTracer(scene).transmittance(up, kInf), 0.75f);  // no Fresnel
}

// glTF alphaMode MASK: a 2 x 2 plane with a 2 x 2 texture whose alpha is 1
// on one diagonal and 0 on the other, cut-off 0.5. Rays at the texel centres
// (makePlane: u = x / 2 + 0.5, t = 1 - v = z / 2 + 0.5) hit the kept cells
// and pass the cut ones, camera and shadow rays alike; without the cut-off
// every ray hits.
TEST(RayTracer, MaskCutsAwayWhereAlphaIsBelowTheCutoff) {
  ShapeDesc plane{ShapeKind::Plane};
  plane.size = 2.0f;
  Scene scene = oneObject(plane, glm::mat4(1.0f));
  Texture texture{"diagonal", 2, 2};
  texture.rgba8 = {200, 50, 50, 255, 200, 50, 50, 0, 200, 50, 50, 0, 200, 50, 50, 255};
  scene.textures.push_back(texture);
  Material& material = scene.objects[0].material;
  material.diffuseMap.texture = 0;
  material.alphaCutoff = 0.5f;
  struct Cell {
    float x, z;
    bool kept;  // texel (column x < 0 ? 0 : 1, row z < 0 ? 0 : 1) has alpha 1
  };
  const Cell cells[] = {
      {-0.5f, -0.5f, true}, {0.5f, -0.5f, false}, {-0.5f, 0.5f, false}, {0.5f, 0.5f, true}};
  for (bool masked : {true, false}) {
    material.alphaCutoff = masked ? 0.5f : 0.0f;
    RayTracer tracer(scene);
    for (const Cell& cell : cells) {
      const bool blocks = !masked || cell.kept;
      const Ray down{{cell.x, 2.0f, cell.z}, {0, -1, 0}};
      EXPECT_EQ(tracer.intersect(down, 0.0f, kInf).has_value(), blocks)
          << "cell " << cell.x << ", " << cell.z << (masked ? " masked" : " unmasked");
      const Ray up{{cell.x, -2.0f, cell.z}, {0, 1, 0}};
      EXPECT_FLOAT_EQ(tracer.transmittance(up, kInf), blocks ? 0.0f : 1.0f);
    }
  }
  // A factor alpha below the cut-off hides the whole surface, texture or not.
  material.alphaCutoff = 0.5f;
  material.alpha = 0.4f;
  EXPECT_FALSE(RayTracer(scene).intersect({{-0.5f, 2.0f, -0.5f}, {0, -1, 0}}, 0.0f, kInf));
}

// A plane seen from below shows its back face. The rasteriser culls it
// unless the material is double-sided, so camera rays pass it too; other
// rays (a reflection, a shadow ray) still meet it, and glass keeps its back
// faces, where refracted rays leave it.
TEST(RayTracer, CameraRaysPassTheBackFacesTheRasteriserCulls) {
  ShapeDesc plane{ShapeKind::Plane};
  plane.size = 4.0f;
  Scene scene = oneObject(plane, glm::mat4(1.0f));
  const Ray up{{0.3f, -2.0f, 0.1f}, {0, 1, 0}};
  auto hits = [&](bool cameraRay) {
    return RayTracer(scene).intersect(up, 0.0f, kInf, cameraRay).has_value();
  };
  EXPECT_FALSE(hits(true));
  EXPECT_TRUE(hits(false));
  EXPECT_FLOAT_EQ(RayTracer(scene).transmittance(up, kInf), 0.0f);
  const Ray down{{0.3f, 2.0f, 0.1f}, {0, -1, 0}};
  EXPECT_TRUE(RayTracer(scene).intersect(down, 0.0f, kInf, true).has_value()) << "front face";
  scene.objects[0].material.doubleSided = true;
  EXPECT_TRUE(hits(true));
  scene.objects[0].material.doubleSided = false;
  scene.objects[0].material.transparency = 0.8f;
  EXPECT_TRUE(hits(true)) << "glass";
}

// A surface made two-sided by listing each triangle twice, wound both ways
// (back-facing copy first): the camera ray passes the back-facing copy and
// still meets the front-facing one at the same distance. (Stepping past a
// back face's distance and searching again lost it: a hole in the trace.)
TEST(RayTracer, CullingKeepsAFrontFaceCoincidentWithABackFace) {
  Mesh quad;
  for (glm::vec3 p :
       {glm::vec3(-1, -1, 0), glm::vec3(1, -1, 0), glm::vec3(1, 1, 0), glm::vec3(-1, 1, 0)})
    quad.vertices.push_back({p, {0, 0, 1}, {0, 0}, {1, 0, 0, 1}});
  quad.indices = {0, 2, 1, 0, 3, 2, 0, 1, 2, 0, 2, 3};  // facing -z, then facing +z
  Scene scene;
  scene.objects.push_back({"quad", scene.addMesh(quad), glm::mat4(1.0f), Material{}});
  RayTracer tracer(scene);
  for (glm::vec2 at : {glm::vec2(0.5f, -0.5f), glm::vec2(-0.5f, 0.5f)}) {
    std::optional<SurfaceHit> hit = tracer.intersect({{at, 3.0f}, {0, 0, -1}}, 0.0f, kInf, true);
    ASSERT_TRUE(hit.has_value()) << at.x << ", " << at.y;
    EXPECT_TRUE(hit->frontFace);
  }
  // From behind, the other copy is the front face.
  EXPECT_TRUE(tracer.intersect({{0.5f, -0.5f, -3.0f}, {0, 0, 1}}, 0.0f, kInf, true).has_value());
}

// Through the uncovered share of a glTF BLEND veil the camera still sees
// straight on: a single-sided plane behind it, seen from behind, is culled
// there too, so the ray ends on the background.
TEST(RayTracer, CameraRaysThroughABlendSurfaceStillPassCulledBackFaces) {
  ShapeDesc plane{ShapeKind::Plane};
  plane.size = 4.0f;
  Scene scene = oneObject(plane, glm::mat4(1.0f));  // faces +y, seen from below: culled
  Material veil;
  veil.ka = veil.kd = glm::vec3(0.0f);
  veil.ks = glm::vec3(0.0f);
  veil.transparency = 1.0f;  // a fully uncovered veil: all of the pixel is what lies behind
  veil.alphaCoverage = true;
  veil.doubleSided = true;
  scene.objects.push_back({"veil", scene.addShape(plane), translation({0.0f, -1.0f, 0.0f}), veil});
  scene.objects[0].material.ka = glm::vec3(1.0f);
  scene.ambient = glm::vec3(1.0f);
  const Ray up{{0.3f, -3.0f, 0.1f}, {0, 1, 0}};
  TraceStats stats;
  const glm::vec3 seen =
      RayTracer(scene).traceRay(up, kInf, up.origin, 0, 1.0f, TraceSettings{}, stats);
  expectNear(seen, scene.background, 1e-6f);
}

TEST(RayTracer, BackFacesAreHitWithTheNormalTurnedToTheRay) {
  ShapeDesc sphere{ShapeKind::Icosphere};
  sphere.radius = 1.0f;
  sphere.tessellation = 1;
  const Scene scene = oneObject(sphere, glm::mat4(1.0f));
  RayTracer tracer(scene);
  std::optional<SurfaceHit> hit = tracer.intersect({{0, 0, 0}, {0, 1, 0}}, 0.0f, kInf);
  ASSERT_TRUE(hit.has_value());
  EXPECT_FALSE(hit->frontFace);
  expectNear(hit->geometricNormal, {0, -1, 0}, 1e-6f);
}

TEST(Bvh, ClosestHitAndCountMatchBruteForceOnTheTeapot) {
  ShapeDesc teapot{ShapeKind::Teapot};
  teapot.tessellation = 6;
  const Mesh mesh = buildShape(teapot);
  const Bvh bvh(mesh);
  EXPECT_LE(bvh.largestLeaf(), 8u);
  EXPECT_LT(bvh.depth(), 40u);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 300; ++i) {
    const Ray ray{glm::vec3(4 * unit(random), 1.5f + 2 * unit(random), 6.0f),
                  glm::vec3(0.3f * unit(random), 0.3f * unit(random), -1.0f)};
    float nearest = kInf;
    uint32_t count = 0, nearestTriangle = 0;
    for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
      const glm::vec3 a = mesh.vertices[mesh.indices[3 * t]].position;
      const glm::vec3 b = mesh.vertices[mesh.indices[3 * t + 1]].position;
      const glm::vec3 c = mesh.vertices[mesh.indices[3 * t + 2]].position;
      TriangleHit h;
      if (intersectTriangle(ray, a, b - a, c - a, 0.0f, kInf, h)) {
        ++count;
        if (h.t < nearest) nearest = h.t, nearestTriangle = t;
      }
    }
    TriangleHit hit;
    const bool found = bvh.intersect(ray, 0.0f, kInf, hit);
    ASSERT_EQ(found, count > 0) << i;
    EXPECT_EQ(bvh.countHits(ray, 0.0f, kInf), count) << i;
    if (!found) continue;
    ++hits;
    EXPECT_EQ(hit.t, nearest) << i;
    EXPECT_EQ(hit.triangle, nearestTriangle) << i;
  }
  EXPECT_GT(hits, 50);  // the rays really test the teapot
}

TEST(Bvh, BarycentricsReconstructTheHitPoint) {
  const glm::vec3 v0{0, 0, 0}, v1{2, 0, 0}, v2{0, 2, 0};
  TriangleHit hit;
  ASSERT_TRUE(
      intersectTriangle({{0.5f, 0.25f, 3}, {0, 0, -1}}, v0, v1 - v0, v2 - v0, 0, kInf, hit));
  EXPECT_FLOAT_EQ(hit.t, 3.0f);
  EXPECT_FLOAT_EQ(hit.u, 0.25f);
  EXPECT_FLOAT_EQ(hit.v, 0.125f);
}

TEST(RayTracer, MeshesShadeWithInterpolatedVertexNormals) {
  Mesh triangle;
  triangle.vertices = {{{0, 0, 0}, {0, 0, 1}, {}, {}},
                       {{2, 0, 0}, glm::normalize(glm::vec3(1, 0, 1)), {}, {}},
                       {{0, 2, 0}, glm::normalize(glm::vec3(0, 1, 1)), {}, {}}};
  triangle.indices = {0, 1, 2};
  Scene scene;
  scene.objects.push_back({"triangle", scene.addMesh(triangle), glm::mat4(1.0f), Material{}});
  RayTracer tracer(scene);
  std::optional<SurfaceHit> hit = tracer.intersect({{0.5f, 0.5f, 3}, {0, 0, -1}}, 0.0f, kInf);
  ASSERT_TRUE(hit.has_value());
  const glm::vec3 expected = 0.5f * glm::vec3(0, 0, 1) +
                             0.25f * glm::normalize(glm::vec3(1, 0, 1)) +
                             0.25f * glm::normalize(glm::vec3(0, 1, 1));
  expectNear(hit->shadingNormal, glm::normalize(expected), 1e-6f);
  expectNear(hit->geometricNormal, {0, 0, 1}, 1e-6f);
}

// The camera ray through a pixel projects back onto that pixel, from depth 0
// to depth 1, with the very matrices the rasteriser uses.
TEST(CameraRays, UnprojectExactlyAsTheProjectionMatrix) {
  for (Projection projection :
       {Projection::Perspective, Projection::Frustum, Projection::Orthographic}) {
    Camera camera;
    camera.projection = projection;
    camera.eye = {1, 2, 6};
    camera.left = -0.6f, camera.right = 0.9f, camera.bottom = -0.4f, camera.top = 0.5f;
    const CameraRays rays(camera, 64, 36);
    const glm::mat4 clip = camera.projectionMatrix(64.0f / 36.0f) * camera.viewMatrix();
    for (glm::vec2 pixel : {glm::vec2(0.5f, 0.5f), glm::vec2(40.25f, 10.75f)}) {
      const Ray ray = rays.through(pixel.x, pixel.y);
      for (float t : {0.0f, 1.0f}) {
        glm::vec4 p = clip * glm::vec4(ray.at(t), 1.0f);
        glm::vec3 ndc = glm::vec3(p) / p.w;
        EXPECT_NEAR((ndc.x + 1) * 32.0f, pixel.x, 2e-3f) << int(projection);
        EXPECT_NEAR((ndc.y + 1) * 18.0f, pixel.y, 2e-3f) << int(projection);
        EXPECT_NEAR(ndc.z, t, 1e-4f) << int(projection);
      }
    }
  }
}

// A near plane 1e7 times closer than the far one: the usual projection's
// far / (near - far) rounds to -1 in a float, and rays unprojected through
// it came out as nothing (a blank trace the rasteriser drew fine). They are
// unprojected through the reversed-Z matrix: from the near plane towards
// the far one, along the view.
TEST(CameraRays, HoldAtAFarToNearRatioOfTenMillion) {
  Camera camera;
  camera.eye = {0, 0, 5};
  camera.near = 1e-5f;
  camera.far = 100.0f;
  const CameraRays rays(camera, 64, 64);
  const Ray ray = rays.through(32.0f, 32.0f);
  EXPECT_NEAR(glm::distance(ray.origin, camera.eye), 1e-5f, 1e-6f);
  EXPECT_NEAR(glm::length(ray.direction), 100.0f - 1e-5f, 1e-3f);
  expectNear(glm::normalize(ray.direction), {0, 0, -1}, 1e-6f);
}

// A camera ray's colour is lighting.cpp's equation in the rasteriser's eye
// space, at the exact surface point.
TEST(RayTracer, LocalShadingIsTheIlluminationEquationInEyeSpace) {
  ShapeDesc sphere{ShapeKind::UvSphere};
  Scene scene = oneObject(sphere, glm::mat4(1.0f));
  scene.objects[0].material = {{0.1f, 0.05f, 0.0f}, {0.6f, 0.3f, 0.2f}, {0.5f, 0.5f, 0.4f}, 24.0f};
  scene.ambient = {0.3f, 0.3f, 0.3f};
  scene.lights = {{LightType::Point, {2, 3, 4}, {}, {0.9f, 0.8f, 0.7f}, {1.0f, 0.1f, 0.02f}},
                  {LightType::Directional, {}, {-1, -0.5f, -1}, {0.2f, 0.2f, 0.3f}, {1, 0, 0}}};
  scene.camera.eye = {0.5f, 1.0f, 5.0f};
  RayTracer tracer(scene);
  const CameraRays rays(scene.camera, 32, 32);
  const Ray ray = rays.through(17.5f, 14.5f);
  std::optional<SurfaceHit> hit = tracer.intersect(ray, 0.0f, 1.0f);
  ASSERT_TRUE(hit.has_value());
  TraceStats stats;
  const glm::vec3 traced =
      tracer.traceRay(ray, 1.0f, rays.viewer(), 0, 1.0f, TraceSettings{}, stats);
  const glm::mat4 view = scene.camera.viewMatrix();
  const Light lights[] = {lightInView(scene.lights[0], view), lightInView(scene.lights[1], view)};
  const glm::vec3 expected =
      illuminate(scene.ambient, lights, glm::vec3(view * glm::vec4(hit->position, 1.0f)),
                 glm::mat3(view) * hit->shadingNormal, scene.objects[0].material, false);
  expectNear(traced, expected, 1e-5f);
  EXPECT_GT(expected.r, 0.2f);  // lit, not just ambient
  EXPECT_EQ(stats.primaryRays, 1u);
  EXPECT_EQ(stats.shadowRays, 2u);
}

// Two facing mirrors and a ray bouncing between them: it stops at the depth
// limit, or where its weight kr^k falls below the contribution threshold.
TEST(RayTracer, RecursionStopsAtTheDepthOrTheContributionThreshold) {
  auto bounces = [](float reflectivity, uint32_t maxDepth) {
    Scene scene;
    ShapeDesc plane{ShapeKind::Plane};
    plane.size = 10.0f;
    const uint32_t mesh = scene.addShape(plane);
    Material mirror;
    mirror.reflectivity = reflectivity;
    scene.objects.push_back({"low", mesh, glm::mat4(1.0f), mirror});
    scene.objects.push_back({"high", mesh, translation({0, 2, 0}), mirror});
    RayTracer tracer(scene);
    TraceSettings settings;
    settings.maxDepth = maxDepth;
    TraceStats stats;
    const Ray ray{{0, 1, 0}, {0, -1, 0}};
    const glm::vec3 colour = tracer.traceRay(ray, kInf, ray.origin, 0, 1.0f, settings, stats);
    EXPECT_TRUE(std::isfinite(colour.r));
    return stats.secondaryRays;
  };
  EXPECT_EQ(bounces(1.0f, 5), 5u);
  EXPECT_EQ(bounces(1.0f, 0), 0u);
  EXPECT_EQ(bounces(0.5f, 20), 9u);    // 0.5^9 = 1/512 is the last ray worth tracing
  EXPECT_EQ(bounces(0.001f, 20), 0u);  // below 1/512 at once
}

TEST(RayTracer, ProgressRisesInHundredthsToOne) {
  ShapeDesc sphere{ShapeKind::UvSphere};
  const Scene scene = oneObject(sphere, glm::mat4(1.0f));
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.width = 8, settings.height = 40, settings.threads = 1;
  std::vector<float> reports;
  settings.progress = [&](float fraction) { reports.push_back(fraction); };
  tracer.render(settings);
  // A report per row here (each row is 2.5 hundredths): 0.02, 0.05, 0.07,
  // ... 0.97 as the 39 first rows complete, then 1.
  ASSERT_EQ(reports.size(), 40u);
  EXPECT_FLOAT_EQ(reports[0], 0.02f);
  EXPECT_FLOAT_EQ(reports[1], 0.05f);
  EXPECT_FLOAT_EQ(reports[38], 0.97f);
  EXPECT_EQ(reports.back(), 1.0f);
  for (size_t i = 1; i < reports.size(); ++i) EXPECT_GT(reports[i], reports[i - 1]);
}

// A billboard of one copy standing at `position` (anchored at its bottom,
// 2 wide and 3 high, scaled by 0.5 across) with a one-texel texture of
// `alpha`, seen by a camera at (0, 4, 10) looking at the origin.
Scene billboardScene(BillboardKind kind, BillboardAlpha mode, uint8_t alpha, glm::vec3 position) {
  Scene scene;
  scene.background = {0.1f, 0.2f, 0.3f};
  scene.ambient = glm::vec3(1.0f);
  scene.camera.eye = {0.0f, 4.0f, 10.0f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.textures.push_back(solidTexture({255, 255, 255, alpha}, TextureRole::Color, "texel"));
  Billboard billboard;
  billboard.name = "tree";
  billboard.kind = kind;
  billboard.alpha = mode;
  billboard.anchor = BillboardAnchor::Bottom;
  billboard.size = {2.0f, 3.0f};
  billboard.material.ka = glm::vec3(0.5f);
  billboard.material.kd = billboard.material.ks = glm::vec3(0.0f);
  billboard.material.diffuseMap.texture = 0;
  billboard.material.alphaCutoff = 0.5f;
  billboard.instances.push_back(translation(position) * scaling({0.5f, 1.0f, 1.0f}));
  scene.billboards.push_back(billboard);
  return scene;
}

// Each kind's quad as billboard.vert places it: the anchor at the middle of
// the bottom edge, the sizes times the copy's scales, and the normal
// (cross(right, up)) towards the eye, across the axis, or out of the image.
TEST(BillboardQuads, EachKindTurnsAsTheVertexStageTurnsIt) {
  const glm::vec3 position{3.0f, 0.0f, -2.0f};
  for (BillboardKind kind :
       {BillboardKind::Screen, BillboardKind::Spherical, BillboardKind::Cylindrical}) {
    const Scene scene = billboardScene(kind, BillboardAlpha::Test, 255, position);
    const Mesh quads = billboardQuads(scene.billboards[0], scene.camera.viewMatrix());
    ASSERT_EQ(quads.vertices.size(), 4u);
    ASSERT_EQ(quads.indices.size(), 6u);
    const Vertex* v = quads.vertices.data();
    expectNear(0.5f * (v[0].position + v[1].position), position, 1e-5f);
    EXPECT_NEAR(glm::length(v[1].position - v[0].position), 1.0f, 1e-5f);  // 2 x 0.5
    EXPECT_NEAR(glm::length(v[3].position - v[0].position), 3.0f, 1e-5f);
    const glm::vec3 right = glm::normalize(v[1].position - v[0].position);
    const glm::vec3 up = glm::normalize(v[3].position - v[0].position);
    expectNear(v[0].normal, glm::cross(right, up), 1e-5f);
    expectNear(glm::vec3(v[0].tangent), right, 1e-5f);
    const glm::vec3 toEye = scene.camera.eye - position;
    if (kind == BillboardKind::Screen) {
      expectNear(v[0].normal, glm::normalize(scene.camera.eye - scene.camera.at), 1e-5f);
    } else if (kind == BillboardKind::Spherical) {
      expectNear(v[0].normal, glm::normalize(toEye), 1e-5f);
    } else {
      expectNear(up, {0.0f, 1.0f, 0.0f}, 1e-5f);
      const glm::vec3 level = glm::normalize(glm::vec3(toEye.x, 0.0f, toEye.z));
      expectNear(v[0].normal, level, 1e-5f);
    }
    // Counter-clockwise seen from the front.
    const glm::vec3 a = v[quads.indices[0]].position, b = v[quads.indices[1]].position,
                    c = v[quads.indices[2]].position;
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), v[0].normal), 0.0f);
    expectNear(glm::vec3(v[2].uv, 0.0f), {1.0f, 1.0f, 0.0f}, 0.0f);
  }
}

// The tracer sees the quad the rasteriser draws: a camera ray through it
// hits the billboard (numbered after the objects), a cut-away texel lets
// the ray pass, a blended texel covers its alpha's share of the pixel, and
// no shadow ray is stopped by it (billboards cast none).
TEST(RayTracer, TracesBillboardsAsTheirQuads) {
  const glm::vec3 position{0.0f, 0.0f, 0.0f};
  Scene scene = billboardScene(BillboardKind::Cylindrical, BillboardAlpha::Test, 255, position);
  scene.objects.push_back(
      {"far", scene.addShape({ShapeKind::UvSphere}), translation({30, 0, 0}), Material{}});
  const Ray ray{scene.camera.eye, glm::vec3(0.0f, 1.5f, 0.0f) - scene.camera.eye};
  {
    RayTracer tracer(scene);
    const std::optional<SurfaceHit> hit = tracer.intersect(ray, 0.0f, kInf, true);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->object, 1u);  // after the one object
    EXPECT_NEAR(hit->t, 1.0f, 1e-4f);
    EXPECT_TRUE(tracer.material(*hit).doubleSided);
    // A shadow ray straight through the quad reaches the light.
    const Ray through{glm::vec3(0.0f, 1.5f, -3.0f), glm::vec3(0.0f, 0.0f, 6.0f)};
    EXPECT_EQ(tracer.transmittance(through, 1.0f), 1.0f);
    TraceStats stats;
    const glm::vec3 lit = tracer.traceRay(ray, kInf, ray.origin, 0, 1.0f, TraceSettings{}, stats);
    expectNear(lit, glm::vec3(0.5f), 1e-5f);  // Ia ka times the white texel
  }
  Scene cut = billboardScene(BillboardKind::Cylindrical, BillboardAlpha::Test, 100, position);
  EXPECT_FALSE(RayTracer(cut).intersect(ray, 0.0f, kInf, true).has_value());
  Scene blended = billboardScene(BillboardKind::Cylindrical, BillboardAlpha::Blend, 64, position);
  blended.billboards[0].material.transparency = 0.5f;
  RayTracer tracer(blended);
  TraceStats stats;
  const glm::vec3 seen = tracer.traceRay(ray, kInf, ray.origin, 0, 1.0f, TraceSettings{}, stats);
  const float coverage = 0.5f * 64.0f / 255.0f;  // 1 - transparency, times the texel's alpha
  expectNear(seen, coverage * glm::vec3(0.5f) + (1.0f - coverage) * blended.background, 1e-5f);
}

// Seeing through a coverage surface is no bounce: a ray through eight
// stacked blended cards whose texels cover nothing reaches the background
// even with no bounces left (it was black past the fifth card, or at once
// with --bounces 0), and half-covering cards weigh it by 0.5 per card.
TEST(RayTracer, SeesThroughStackedCoverageWithoutSpendingBounces) {
  for (uint8_t alpha : {uint8_t(0), uint8_t(128)}) {
    Scene scene = billboardScene(BillboardKind::Screen, BillboardAlpha::Blend, alpha, glm::vec3(0));
    scene.camera.eye = {0.0f, 0.0f, 10.0f};  // looking down -z through every card's centre
    Billboard& cards = scene.billboards[0];
    cards.anchor = BillboardAnchor::Center;
    cards.instances.clear();
    for (int i = 0; i < 8; ++i) cards.instances.push_back(translation({0.0f, 0.0f, -float(i)}));
    RayTracer tracer(scene);
    const Ray ray{scene.camera.eye, -scene.camera.eye};
    TraceSettings settings;
    settings.maxDepth = 0;
    TraceStats stats;
    const glm::vec3 seen = tracer.traceRay(ray, kInf, ray.origin, 0, 1.0f, settings, stats);
    const float covered = float(alpha) / 255.0f, behind = std::pow(1.0f - covered, 8.0f);
    // Each card's own colour is Ia ka = 0.5, times its coverage.
    float expected = 0.0f, through = 1.0f;
    for (int i = 0; i < 8; ++i, through *= 1.0f - covered) expected += through * covered * 0.5f;
    expectNear(seen, glm::vec3(expected) + behind * scene.background, 1e-4f);
    EXPECT_EQ(stats.primaryRays, 1u);
    EXPECT_EQ(stats.secondaryRays, 8u);  // one per card seen through
  }
}

// A glTF BLEND card's shadow: a shadow ray passes what the texel leaves
// uncovered, (1 - kt) times the texel's alpha, once per crossing.
TEST(RayTracer, BlendedCardsPassTheLightTheirTexelsDoNotCover) {
  Scene scene;
  scene.textures.push_back(solidTexture({255, 255, 255, 64}, TextureRole::Color, "texel"));
  Material card;
  card.alphaCoverage = true;
  card.transparency = 0.5f;
  card.diffuseMap.texture = 0;
  const uint32_t plane = scene.addShape({ShapeKind::Plane, 4.0f});
  scene.objects.push_back({"card", plane, translation({0, 1, 0}), card});
  scene.objects.push_back({"card above", plane, translation({0, 2, 0}), card});
  RayTracer tracer(scene);
  const float passes = 1.0f - 0.5f * 64.0f / 255.0f;
  const Ray up{{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
  EXPECT_NEAR(tracer.transmittance(up, 1.5f), passes, 1e-6f);
  EXPECT_NEAR(tracer.transmittance(up, kInf), passes * passes, 1e-6f);
}

// A normal map on a double-sided plane (normal +y, tangent +x) tilts the
// front's normal to (0.6, 0.8, 0); seen from below, the surface's normal is
// that one negated, as the shaders negate the bumped normal of a back face
// (the mirrored tilt, (0.6, -0.8, 0), lit 0.28 here). Lit by a light
// straight along that normal, N.L = 1.
TEST(RayTracer, BackFacesAreBumpedAsTheFrontNegated) {
  Scene scene;
  scene.ambient = glm::vec3(0.0f);
  scene.textures.push_back(solidTexture({204, 128, 230, 255}, TextureRole::Data, "tilt"));
  Material bumped;
  bumped.kd = glm::vec3(1.0f);
  bumped.ks = glm::vec3(0.0f);
  bumped.normalMap.texture = 0;
  bumped.doubleSided = true;
  scene.objects.push_back(
      {"plane", scene.addShape({ShapeKind::Plane, 4.0f}), glm::mat4(1.0f), bumped});
  TraceSettings settings;
  settings.shadows = false;
  for (float side : {1.0f, -1.0f}) {
    scene.lights = {
        {LightType::Directional, {}, -side * glm::vec3(0.6f, 0.8f, 0.0f), glm::vec3(1.0f)}};
    RayTracer tracer(scene);
    const Ray ray{{0.0f, 5.0f * side, 0.0f}, {0.0f, -side, 0.0f}};
    TraceStats stats;
    const glm::vec3 lit =
        tracer.traceRay(ray, kInf, ray.origin, 0, 1.0f, settings, stats, {}, false);
    EXPECT_NEAR(lit.r, 1.0f, 0.01f) << (side > 0 ? "front" : "back");
  }
}

// Billboard sizes and positions near the float range (the scene format
// takes any finite number): the quads are built and traced without a
// throw, and every pixel stays finite.
TEST(RayTracer, BillboardsNearTheFloatRangeTraceFinite) {
  Scene scene = billboardScene(BillboardKind::Spherical, BillboardAlpha::Test, 255, glm::vec3(0));
  scene.billboards[0].size = {1e30f, 1e30f};
  scene.billboards[0].instances.push_back(translation({3e38f, 0.0f, 0.0f}));
  scene.billboards[0].instances.push_back(translation({0.0f, 0.0f, 10.0f}));
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.width = 8, settings.height = 6;
  TraceResult result;
  ASSERT_NO_THROW(result = tracer.render(settings));
  for (uint32_t y = 0; y < settings.height; ++y)
    for (uint32_t x = 0; x < settings.width; ++x) {
      const glm::vec4 pixel = result.image.at(x, y);
      EXPECT_TRUE(std::isfinite(pixel.r) && std::isfinite(pixel.g) && std::isfinite(pixel.b))
          << x << "," << y;
    }
}

// Billboards face the camera the tracer was built for; rendering after the
// camera moved would show them turned towards the old one, so it throws.
TEST(RayTracer, RefusesToRenderBillboardsForAMovedCamera) {
  Scene scene = billboardScene(BillboardKind::Spherical, BillboardAlpha::Test, 255, glm::vec3(0));
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.width = settings.height = 4;
  EXPECT_NO_THROW(tracer.render(settings));
  scene.camera.eye.x += 1.0f;
  EXPECT_THROW(tracer.render(settings), std::logic_error);
}

TEST(RayTracer, SampleCountsMustBeSquares) {
  EXPECT_NO_THROW(checkSamplesPerPixel(1));
  EXPECT_NO_THROW(checkSamplesPerPixel(16));
  EXPECT_THROW(checkSamplesPerPixel(8), InputError);
  EXPECT_THROW(checkSamplesPerPixel(0), InputError);
}

}  // namespace
}  // namespace shadelab
