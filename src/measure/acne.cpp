#include "measure/acne.h"

#include <cmath>
#include <optional>

#include "core/scene/transform.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

constexpr glm::dvec3 kSphereCentre{0.0, 0.3, 0.0};

// Whether the point is lit in exact arithmetic, or nullopt within `margin` of
// a shadow boundary (the terminator, the shadow's edge), where rounding may
// decide either way and neither answer is wrong.
std::optional<bool> trulyLit(glm::dvec3 point, glm::dvec3 normal, glm::dvec3 toLight,
                             bool onSphere) {
  const double margin = 0.02;
  const double facing = glm::dot(normal, toLight);
  if (std::abs(facing) < margin) return std::nullopt;
  if (facing < 0.0) return false;
  if (onSphere) return true;  // a convex surface shadows itself only past the terminator
  const double along = glm::dot(kSphereCentre - point, toLight);
  const double distance = glm::length(kSphereCentre - point - along * toLight);
  if (along > 0.0 && std::abs(distance - 1.0) < margin) return std::nullopt;
  return !(along > 0.0 && distance < 1.0);
}

}  // namespace

Scene acneScene() {
  Scene scene;
  scene.name = "acne";
  scene.camera.eye = {0.0f, 3.0f, 7.0f};
  scene.camera.at = {0.0f, 0.0f, 0.0f};
  scene.ambient = glm::vec3(0.2f);
  const float elevation = glm::radians(30.0f);
  scene.lights.push_back({LightType::Directional,
                          {},
                          -glm::vec3(std::cos(elevation), std::sin(elevation), 0.3f),
                          glm::vec3(1.0f),
                          {1, 0, 0}});
  ShapeDesc plane{ShapeKind::Plane};
  plane.size = 12.0f;
  ShapeDesc sphere{ShapeKind::UvSphere};
  sphere.radius = 1.0f;
  scene.objects.push_back({"floor", scene.addShape(plane), translation({0, -0.7f, 0}), Material{}});
  scene.objects.push_back(
      {"sphere", scene.addShape(sphere), translation(glm::vec3(kSphereCentre)), Material{}});
  return scene;
}

AcneMeasurement measureAcne(const Scene& scene, float epsilon, uint32_t width, uint32_t height) {
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.width = width, settings.height = height, settings.epsilon = epsilon;
  settings.maxDepth = 0;
  AcneMeasurement result;
  result.epsilon = epsilon;
  result.image = tracer.render(settings).image;
  settings.shadows = false;
  const ImageRgba unshadowed = tracer.render(settings).image;
  const CameraRays rays(scene.camera, width, height);
  const glm::dvec3 toLight = glm::normalize(-glm::dvec3(scene.lights[0].direction));
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      std::optional<SurfaceHit> hit =
          tracer.intersect(rays.through(float(x) + 0.5f, float(y) + 0.5f), 0.0f, 1.0f, true);
      if (!hit) continue;
      const bool onSphere = hit->object == 1;
      std::optional<bool> truth = trulyLit(hit->position, hit->shadingNormal, toLight, onSphere);
      if (!truth) continue;
      // Lit or not as the tracer drew it: darker than without shadow rays.
      const bool drawnShadowed = result.image.at(x, y).g < unshadowed.at(x, y).g - 1e-4f;
      if (*truth) {
        ++result.litPixels;
        result.acnePixels += drawnShadowed;
        result.acneOnSphere += drawnShadowed && onSphere;
      } else if (!onSphere && glm::dot(glm::dvec3(hit->shadingNormal), toLight) > 0.0) {
        // Only the sphere's cast shadow: surfaces facing away are unlit by the
        // equation itself, whatever the shadow ray does.
        ++result.shadowedPixels;
        result.leakingPixels += !drawnShadowed;
      }
    }
  return result;
}

}  // namespace shadelab
