// Where ray tracing fails, measured: shadow acne without the epsilon offset,
// total internal reflection, rays parallel to surfaces, a camera inside a
// sphere; and the determinism the reference needs (any thread count, the
// same bits).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "core/scene/transform.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

bool finite(glm::vec3 c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

ShapeDesc sphereShape(float radius) {
  ShapeDesc shape{ShapeKind::UvSphere};
  shape.radius = radius;
  return shape;
}

ShapeDesc planeShape(float size) {
  ShapeDesc shape{ShapeKind::Plane};
  shape.size = size;
  return shape;
}

// A floor (at y = -0.7, moved there by its transform as in most scenes) and
// a unit sphere on it, lit by a directional light 30 degrees above the
// horizon: the low angle that makes acne easy to get.
Scene acneScene() {
  Scene scene;
  scene.camera.eye = {0.0f, 3.0f, 7.0f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.ambient = glm::vec3(0.2f);
  const float elevation = glm::radians(30.0f);
  scene.lights.push_back({LightType::Directional,
                          {},
                          -glm::vec3(std::cos(elevation), std::sin(elevation), 0.3f),
                          glm::vec3(1.0f),
                          {1, 0, 0}});
  scene.objects.push_back(
      {"floor", scene.addShape(planeShape(12.0f)), translation({0, -0.7f, 0}), Material{}});
  scene.objects.push_back(
      {"sphere", scene.addShape(sphereShape(1.0f)), translation({0, 0.3f, 0}), Material{}});
  return scene;
}

// Whether the point is lit in exact arithmetic, or nullopt within `margin` of
// a shadow boundary (the terminator, the shadow's edge), where rounding may
// decide either way and neither answer is acne.
std::optional<bool> trulyLit(glm::dvec3 point, glm::dvec3 normal, glm::dvec3 toLight,
                             bool onSphere) {
  const double margin = 0.02;
  const double facing = glm::dot(normal, toLight);
  if (std::abs(facing) < margin) return std::nullopt;
  if (facing < 0.0) return false;
  if (onSphere) return true;  // a convex surface shadows itself only past the terminator
  const glm::dvec3 centre{0, 0.3, 0};
  const double along = glm::dot(centre - point, toLight);
  const double distance = glm::length(centre - point - along * toLight);
  if (along > 0.0 && std::abs(distance - 1.0) < margin) return std::nullopt;
  return !(along > 0.0 && distance < 1.0);
}

// Acne pixels: lit in truth, darker with shadow rays than without them.
double acneFraction(const Scene& scene, float epsilon) {
  constexpr uint32_t w = 160, h = 90;
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.width = w, settings.height = h, settings.epsilon = epsilon;
  settings.maxDepth = 0;
  const ImageRgba shadowed = tracer.render(settings).image;
  settings.shadows = false;
  const ImageRgba unshadowed = tracer.render(settings).image;
  const CameraRays rays(scene.camera, w, h);
  const glm::dvec3 toLight = glm::normalize(-glm::dvec3(scene.lights[0].direction));
  uint32_t lit = 0, acne = 0, acneOnSphere = 0;
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      std::optional<SurfaceHit> hit =
          tracer.intersect(rays.through(x + 0.5f, y + 0.5f), 0.0f, 1.0f);
      if (!hit) continue;
      std::optional<bool> truth =
          trulyLit(hit->position, hit->shadingNormal, toLight, hit->object == 1);
      if (!truth || !*truth) continue;
      ++lit;
      const bool wronglyShadowed = shadowed.at(x, y).g < unshadowed.at(x, y).g - 1e-4f;
      acne += wronglyShadowed;
      acneOnSphere += wronglyShadowed && hit->object == 1;
    }
  }
  std::printf("epsilon %g: %u of %u lit pixels shadowed (%u on the sphere)\n", epsilon, acne, lit,
              acneOnSphere);
  EXPECT_GT(lit, w * h / 4) << "the test must look at many lit pixels";
  return double(acne) / double(lit);
}

TEST(TraceStability, ShadowAcneWithoutEpsilonAndNoneWithIt) {
  const Scene scene = acneScene();
  const double withoutOffset = acneFraction(scene, 0.0f);
  const double withOffset = acneFraction(scene, TraceSettings{}.epsilon);
  std::printf("shadow acne: %.1f%% of lit pixels with epsilon 0, %.2f%% with epsilon %g\n",
              100.0 * withoutOffset, 100.0 * withOffset, TraceSettings{}.epsilon);
  EXPECT_GT(withoutOffset, 0.10);
  EXPECT_LT(withOffset, 0.001);
}

// A black glass sphere (kt 1, ior 1.5, no local colour) around the ray's origin.
Scene glassBall() {
  Scene scene;
  scene.background = {0.2f, 0.4f, 0.6f};
  Material glass{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1.0f};
  glass.transparency = 1.0f;
  glass.ior = 1.5f;
  scene.objects.push_back({"glass", scene.addShape(sphereShape(1.0f)), glm::mat4(1.0f), glass});
  return scene;
}

TEST(TraceStability, TotalInternalReflectionTrapsAGrazingRayInsideGlass) {
  const Scene scene = glassBall();
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.maxDepth = 8;
  // A chord 0.9 from the centre meets the wall at asin(0.9) = 64 degrees,
  // beyond glass's critical angle of 41.8: it reflects every time, never leaves.
  TraceStats grazing;
  const Ray inside{{-0.3f, 0.9f, 0.0f}, {1.0f, 0.0f, 0.0f}};
  const glm::vec3 trapped =
      tracer.traceRay(inside, kInf, inside.origin, 0, 1.0f, settings, grazing);
  EXPECT_TRUE(finite(trapped));
  EXPECT_EQ(trapped, glm::vec3(0.0f));
  EXPECT_EQ(grazing.totalInternalReflections, settings.maxDepth);
  // A chord 0.3 from the centre (17 degrees) leaves at once and sees the
  // background: all of it without Fresnel; with it, 1 - F at once and the
  // rest after more bounces inside, short only of what maxDepth and
  // minContribution cut off (0.0012 measured).
  TraceStats steep;
  const Ray out{{-0.3f, 0.3f, 0.0f}, {1.0f, 0.0f, 0.0f}};
  settings.fresnel = false;
  const glm::vec3 escaped = tracer.traceRay(out, kInf, out.origin, 0, 1.0f, settings, steep);
  EXPECT_EQ(steep.totalInternalReflections, 0u);
  EXPECT_NEAR(glm::length(escaped - scene.background), 0.0f, 1e-6f);
  settings.fresnel = true;
  const glm::vec3 withFresnel = tracer.traceRay(out, kInf, out.origin, 0, 1.0f, settings, steep);
  EXPECT_LT(glm::length(scene.background - withFresnel), 0.005f);
  EXPECT_GT(glm::length(scene.background - withFresnel), 0.0f);
}

TEST(TraceStability, RaysParallelToAPlaneMissIt) {
  Scene scene;
  scene.background = {0.3f, 0.2f, 0.1f};
  scene.objects.push_back({"floor", scene.addShape(planeShape(4.0f)), glm::mat4(1.0f), Material{}});
  RayTracer tracer(scene);
  TraceStats stats;
  for (const Ray& ray : {Ray{{-5, 0, 0}, {1, 0, 0}}, Ray{{-5, 0.5f, 0.3f}, {1, 0, 0}},
                         Ray{{-5, 0, -5}, glm::normalize(glm::vec3(1, 0, 1))}}) {
    EXPECT_FALSE(tracer.intersect(ray, 0.0f, kInf).has_value());
    const glm::vec3 colour =
        tracer.traceRay(ray, kInf, ray.origin, 0, 1.0f, TraceSettings{}, stats);
    EXPECT_EQ(colour, scene.background);
    EXPECT_EQ(tracer.transmittance(ray, kInf), 1.0f);
  }
}

TEST(TraceStability, RaysParallelToATriangleMissIt) {
  // A tilted triangle (not axis-aligned, so the determinant is rounding
  // noise, not an exact zero) and rays in and beside its plane.
  const glm::mat4 tilt = rotationAxis({1, 2, 3}, 0.7f);
  const glm::vec3 a = glm::vec3(tilt * glm::vec4(0, 0, 0, 1));
  const glm::vec3 b = glm::vec3(tilt * glm::vec4(2, 0, 0, 1));
  const glm::vec3 c = glm::vec3(tilt * glm::vec4(0, 2, 0, 1));
  const glm::vec3 inPlane = glm::mat3(tilt) * glm::vec3(1, 0.3f, 0);
  const glm::vec3 normal = glm::mat3(tilt) * glm::vec3(0, 0, 1);
  const glm::vec3 start = glm::vec3(tilt * glm::vec4(-1, 0.2f, 0, 1));
  TriangleHit hit;
  EXPECT_FALSE(intersectTriangle({start, inPlane}, a, b - a, c - a, 0.0f, kInf, hit));
  EXPECT_FALSE(
      intersectTriangle({start + 0.1f * normal, inPlane}, a, b - a, c - a, 0.0f, kInf, hit));
  // The same triangle is hit by a ray across it, so the misses are real.
  EXPECT_TRUE(intersectTriangle({start + normal + 1.2f * inPlane, -normal}, a, b - a, c - a, 0.0f,
                                kInf, hit));
  EXPECT_NEAR(hit.t, 1.0f, 1e-5f);
}

TEST(TraceStability, CameraInsideASphereSeesItsLitOrUnlitInside) {
  Scene scene;
  scene.camera.eye = {0, 0, 0};
  scene.camera.at = {0, 0, -1};
  scene.ambient = glm::vec3(0.5f);
  Material wall{glm::vec3(0.2f, 0.3f, 0.4f), glm::vec3(0.7f), glm::vec3(0.3f), 16.0f};
  scene.objects.push_back({"room", scene.addShape(sphereShape(2.0f)), glm::mat4(1.0f), wall});
  scene.lights.push_back({LightType::Point, {0, 5, 0}, {}, glm::vec3(1.0f), {1, 0, 0}});
  TraceSettings settings;
  settings.width = 32, settings.height = 18;
  // The light outside: the sphere shadows all of its own inside, ambient only.
  ImageRgba outside = RayTracer(scene).render(settings).image;
  const glm::vec3 ambient = scene.ambient * wall.ka;
  for (uint32_t y = 0; y < settings.height; ++y)
    for (uint32_t x = 0; x < settings.width; ++x) {
      const glm::vec3 c = glm::vec3(outside.at(x, y));
      ASSERT_TRUE(finite(c)) << x << "," << y;
      EXPECT_NEAR(glm::length(c - ambient), 0.0f, 1e-6f) << x << "," << y;
    }
  // The light inside: every point of the inside sees it, nothing is NaN.
  scene.lights[0].position = {0, 1.5f, 0};
  ImageRgba inside = RayTracer(scene).render(settings).image;
  uint32_t brighter = 0;
  for (uint32_t y = 0; y < settings.height; ++y)
    for (uint32_t x = 0; x < settings.width; ++x) {
      const glm::vec3 c = glm::vec3(inside.at(x, y));
      ASSERT_TRUE(finite(c));
      brighter += c.g > ambient.g + 0.05f;
    }
  EXPECT_EQ(brighter, settings.width * settings.height);
}

TEST(TraceStability, CollapsedObjectsAreNotThereAndLeaveNoNaN) {
  Scene scene;
  scene.background = {0.25f, 0.5f, 0.75f};
  scene.camera.eye = {0, 0, 5};
  scene.lights.push_back({LightType::Point, {0, 3, 3}, {}, glm::vec3(1.0f), {1, 0, 0}});
  scene.objects.push_back(
      {"flat", scene.addShape(sphereShape(1.0f)), scaling({1.0f, 0.0f, 1.0f}), Material{}});
  scene.objects.push_back(
      {"gone", scene.addShape(planeShape(2.0f)), scaling(glm::vec3(0.0f)), Material{}});
  TraceSettings settings;
  settings.width = 16, settings.height = 9;
  const ImageRgba image = RayTracer(scene).render(settings).image;
  for (uint32_t y = 0; y < settings.height; ++y)
    for (uint32_t x = 0; x < settings.width; ++x)
      EXPECT_EQ(glm::vec3(image.at(x, y)), scene.background) << x << "," << y;
}

TEST(TraceStability, ImageIsBitIdenticalForAnyThreadCount) {
  const Scene scene = builtinScene("whitted");
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.width = 64, settings.height = 36, settings.samplesPerPixel = 4;
  settings.threads = 1;
  const TraceResult one = tracer.render(settings);
  settings.threads = 4;
  const TraceResult four = tracer.render(settings);
  ASSERT_EQ(one.image.pixels.size(), four.image.pixels.size());
  EXPECT_EQ(std::memcmp(one.image.pixels.data(), four.image.pixels.data(),
                        one.image.pixels.size() * sizeof(float)),
            0);
  EXPECT_EQ(one.stats.total(), four.stats.total());
  EXPECT_GT(one.stats.secondaryRays, 0u);  // reflection and refraction were exercised
}

}  // namespace
}  // namespace shadelab
