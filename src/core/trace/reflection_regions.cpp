#include "core/trace/reflection_regions.h"

#include <algorithm>
#include <cassert>
#include <limits>

#include "core/trace/ray.h"
#include "core/trace/raytracer.h"

namespace shadelab {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// A refracted path bouncing inside its object (total internal reflection)
// longer than this is not followed further: it is counted as not escaping.
constexpr int kMaxInternalBounces = 8;

// Off the surface on the side the ray leaves towards (RayTracer's epsilon).
Ray leaving(const SurfaceHit& hit, glm::vec3 direction) {
  const float side = glm::dot(direction, hit.geometricNormal) >= 0.0f ? 1.0f : -1.0f;
  const glm::vec3 magnitude = glm::abs(hit.position);
  const float scale = std::max({1.0f, magnitude.x, magnitude.y, magnitude.z});
  return {hit.position + side * 1e-4f * scale * hit.geometricNormal, direction};
}

ReflectionRegion classify(const RayTracer& tracer, const Ray& camera) {
  std::optional<SurfaceHit> hit = tracer.intersect(camera, 0.0f, 1.0f, true);
  if (!hit) return ReflectionRegion::None;
  const Material& material = tracer.material(*hit);
  if (material.reflectivity <= 0.0f && material.transparency <= 0.0f) return ReflectionRegion::None;
  const bool refracts = material.transparency > material.reflectivity;
  glm::vec3 incident = glm::normalize(camera.direction);
  for (int bounce = 0; bounce <= kMaxInternalBounces; ++bounce) {
    glm::vec3 direction = mirrorDirection(incident, hit->shadingNormal);
    if (refracts) {
      const float eta = hit->frontFace ? 1.0f / material.ior : material.ior;
      direction = refractDirection(incident, hit->shadingNormal, eta).value_or(direction);
    }
    const Ray next = leaving(*hit, glm::normalize(direction));
    const std::optional<SurfaceHit> further = tracer.intersect(next, 0.0f, kInfinity);
    if (!further) return ReflectionRegion::Escapes;
    // Environment mapping refracts once, as if through the object to the
    // environment: crossing the object's own inside is part of that path.
    if (!refracts || further->object != hit->object) return ReflectionRegion::HitsObject;
    incident = next.direction;
    hit = further;
  }
  return ReflectionRegion::HitsObject;
}

}  // namespace

uint64_t ReflectionRegions::count(ReflectionRegion region) const {
  return uint64_t(std::count(pixels.begin(), pixels.end(), region));
}

ReflectionRegions classifyReflections(const Scene& scene, uint32_t width, uint32_t height) {
  const RayTracer tracer(scene);
  const CameraRays rays(scene.camera, width, height);
  ReflectionRegions regions{width, height, std::vector<ReflectionRegion>(size_t(width) * height)};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x)
      regions.pixels[size_t(y) * width + x] =
          classify(tracer, rays.through(float(x) + 0.5f, float(y) + 0.5f));
  return regions;
}

double meanOver(const MetricMap& map, const ReflectionRegions& regions, ReflectionRegion region) {
  assert(map.width == regions.width && map.height == regions.height);
  double sum = 0.0;
  uint64_t count = 0;
  for (size_t i = 0; i < regions.pixels.size(); ++i)
    if (regions.pixels[i] == region) sum += map.values[i], ++count;
  return count ? sum / double(count) : 0.0;
}

ImageU8 regionImage(const ReflectionRegions& regions) {
  ImageU8 image(regions.width, regions.height);
  for (uint32_t y = 0; y < regions.height; ++y)
    for (uint32_t x = 0; x < regions.width; ++x) {
      const ReflectionRegion region = regions.pixels[size_t(y) * regions.width + x];
      image.set(x, y,
                region == ReflectionRegion::Escapes      ? glm::u8vec4{70, 130, 230, 255}
                : region == ReflectionRegion::HitsObject ? glm::u8vec4{240, 140, 40, 255}
                                                         : glm::u8vec4{40, 40, 44, 255});
    }
  return image;
}

}  // namespace shadelab
