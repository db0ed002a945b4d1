#include "measure/tir.h"

#include <cmath>

#include "core/scene/transform.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

Object emitter(Scene& scene, const char* name, float y, glm::vec3 colour) {
  ShapeDesc plane{ShapeKind::Plane};
  plane.size = 4000.0f;
  Material material{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1.0f};
  material.emissive = colour;
  return {name, scene.addShape(plane), translation({0.0f, y, 0.0f}), material};
}

}  // namespace

Scene tirScene(float ior) {
  Scene scene;
  scene.name = "tir";
  scene.ambient = glm::vec3(0.0f);
  scene.background = glm::vec3(0.0f);
  ShapeDesc surface{ShapeKind::Plane};
  surface.size = 4000.0f;
  Material glass{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 1.0f};
  glass.transparency = 1.0f;
  glass.ior = ior;
  scene.objects.push_back({"glass surface", scene.addShape(surface), glm::mat4(1.0f), glass});
  scene.objects.push_back(emitter(scene, "transmitted", 1.0f, {1.0f, 0.0f, 0.0f}));
  scene.objects.push_back(emitter(scene, "reflected", -2.0f, {0.0f, 1.0f, 0.0f}));
  return scene;
}

TirSample measureInterface(float ior, double angleDegrees) {
  const Scene scene = tirScene(ior);
  RayTracer tracer(scene);
  TraceSettings settings;
  settings.maxDepth = 1;
  const double angle = glm::radians(angleDegrees);
  const Ray ray{{0.0f, -1.0f, 0.0f}, glm::vec3(std::sin(angle), std::cos(angle), 0.0)};
  TraceStats stats;
  const glm::vec3 colour = tracer.traceRay(ray, 1e30f, ray.origin, 0, 1.0f, settings, stats);
  return {ior, angleDegrees, colour.r, colour.g, stats.totalInternalReflections > 0};
}

double tracedCriticalAngle(float ior) {
  double below = 0.0, above = 90.0;  // no TIR at `below`, TIR at `above`
  while (above - below > 1e-6) {
    const double middle = 0.5 * (below + above);
    (measureInterface(ior, middle).totalInternalReflection ? above : below) = middle;
  }
  return above;
}

double schlickReflectance(double ior, double angleDegrees) {
  const double sinInside = ior * std::sin(glm::radians(angleDegrees));
  if (sinInside >= 1.0) return 1.0;
  const double cosAir = std::sqrt(1.0 - sinInside * sinInside);
  const double f0 = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
  return f0 + (1.0 - f0) * std::pow(1.0 - cosAir, 5.0);
}

double exactReflectance(double ior, double angleDegrees) {
  const double cosI = std::cos(glm::radians(angleDegrees));
  const double sinT = ior * std::sin(glm::radians(angleDegrees));
  if (sinT >= 1.0) return 1.0;
  const double cosT = std::sqrt(1.0 - sinT * sinT);
  // Fresnel's equations, n1 = ior inside, n2 = 1 outside.
  const double perpendicular = (ior * cosI - cosT) / (ior * cosI + cosT);
  const double parallel = (cosI - ior * cosT) / (cosI + ior * cosT);
  return 0.5 * (perpendicular * perpendicular + parallel * parallel);
}

ImageRgba snellsWindow(float ior, uint32_t width, uint32_t height) {
  Scene scene = tirScene(ior);
  scene.camera.eye = {0.0f, -0.5f, 0.0f};
  scene.camera.at = {0.0f, 0.5f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.camera.fovyDegrees = 150.0f;
  scene.camera.near = 0.01f;
  scene.camera.far = 100.0f;
  TraceSettings settings;
  settings.width = width, settings.height = height, settings.samplesPerPixel = 4;
  settings.maxDepth = 1;
  settings.shadows = false;
  return RayTracer(scene).render(settings).image;
}

}  // namespace shadelab
