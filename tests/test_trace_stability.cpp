// Where ray tracing fails, measured (shadow acne: tests/test_trace_studies.cpp):
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
  // Seen from inside, as a double-sided surface (a single-sided one is culled: below).
  wall.doubleSided = true;
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
  // Single-sided, the inside is all back faces: the camera rays pass them as
  // the rasteriser culls them, and every pixel is the background.
  scene.objects[0].material.doubleSided = false;
  ImageRgba culled = RayTracer(scene).render(settings).image;
  for (uint32_t y = 0; y < settings.height; ++y)
    for (uint32_t x = 0; x < settings.width; ++x)
      EXPECT_EQ(glm::vec3(culled.at(x, y)), scene.background) << x << "," << y;
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
