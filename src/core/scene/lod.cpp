#include "core/scene/lod.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/scene/frustum.h"

namespace shadelab {
namespace {

constexpr float kPi = 3.14159265358979f;

// The largest factor by which the transform stretches a length.
float maxScale(const glm::mat4& transform) {
  return std::max({glm::length(glm::vec3(transform[0])), glm::length(glm::vec3(transform[1])),
                   glm::length(glm::vec3(transform[2]))});
}

// Per mesh: the smallest world-space error any object drawing it tolerates,
// expressed in the mesh's own units (divided by the object's scale).
std::vector<float> toleratedObjectErrors(const Scene& scene, const ViewSize& view,
                                         float maxErrorPixels) {
  std::vector<float> errors(scene.meshes.size(), std::numeric_limits<float>::infinity());
  for (const Object& object : scene.objects) {
    Bounds box = transformBounds(computeBounds(scene.meshes[object.mesh]), object.transform);
    float ppu = pixelsPerUnitForSphere(view, centre(box), boundingRadius(box));
    float worldError = maxErrorPixels / ppu;
    float objectError = worldError / std::max(maxScale(object.transform), 1e-12f);
    errors[object.mesh] = std::min(errors[object.mesh], objectError);
  }
  return errors;
}

uint32_t tessellationFor(const ShapeDesc& shape, float error) {
  switch (shape.kind) {
    case ShapeKind::UvSphere:
      return std::clamp(segmentsForChordError(shape.radius, error), 3u, 1024u);
    case ShapeKind::Torus: {
      // The ring's outer circle and the tube, which gets half the segments.
      uint32_t ring = segmentsForChordError(shape.majorRadius + shape.minorRadius, error);
      uint32_t tube = segmentsForChordError(shape.minorRadius, error);
      return std::clamp(std::max(ring, 2 * tube), 3u, 1024u);
    }
    case ShapeKind::Icosphere: {
      // An icosahedron's edge subtends 1.107 rad; each level halves it, and
      // the sagitta of an edge subtending theta is r (1 - cos(theta / 2)).
      for (uint32_t level = 0; level < 7; ++level) {
        float theta = 1.1071487f / float(1u << level);
        if (shape.radius * (1.0f - std::cos(theta * 0.5f)) <= error) return level;
      }
      return 7;
    }
    case ShapeKind::Teapot:
      // Four patches around the body of radius 2, n quads each.
      return std::clamp((segmentsForChordError(2.0f, error) + 3) / 4, 1u, 64u);
    default:
      return shape.tessellation;
  }
}

}  // namespace

float pixelsPerUnit(const ViewSize& view, float depth) {
  const Camera& camera = view.camera;
  float height = float(view.height);
  switch (camera.projection) {
    case Projection::Orthographic:
      return height / (camera.top - camera.bottom);
    case Projection::Frustum:
      return height * camera.near / ((camera.top - camera.bottom) * depth);
    case Projection::Perspective:
    default:
      return height / (2.0f * depth * std::tan(glm::radians(camera.fovyDegrees) * 0.5f));
  }
}

float pixelsPerUnitForSphere(const ViewSize& view, glm::vec3 centre, float radius) {
  glm::vec3 forward = glm::normalize(view.camera.at - view.camera.eye);
  float depth = glm::dot(centre - view.camera.eye, forward) - radius;
  return pixelsPerUnit(view, std::max(depth, view.camera.near));
}

uint32_t segmentsForChordError(float radius, float maxError) {
  if (!(maxError > 0.0f) || maxError >= radius) return 3;
  // r (1 - cos(pi / n)) <= e  <=>  n >= pi / acos(1 - e / r)
  double n = std::ceil(double(kPi) / std::acos(1.0 - double(maxError) / double(radius)));
  return uint32_t(std::clamp(n, 3.0, 1e6));
}

void tessellateForView(Scene& scene, const ViewSize& view, float maxErrorPixels) {
  std::vector<float> errors = toleratedObjectErrors(scene, view, maxErrorPixels);
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    ShapeDesc& shape = scene.shapes[i];
    if (shape.kind == ShapeKind::Custom) continue;
    // A mesh no object draws (infinite error) keeps its tessellation.
    uint32_t tessellation =
        std::isinf(errors[i]) ? shape.tessellation : tessellationFor(shape, errors[i]);
    // Built at the description itself (scale 1), also after a retessellate.
    if (tessellation == shape.tessellation && scene.tessellationScale == 1.0f) continue;
    shape.tessellation = tessellation;
    scene.meshes[i] = buildShape(shape);
  }
  scene.tessellationScale = 1.0f;
}

SimplifyStats simplifyForView(Scene& scene, const ViewSize& view, float maxErrorPixels) {
  std::vector<float> errors = toleratedObjectErrors(scene, view, maxErrorPixels);
  SimplifyStats stats;
  for (size_t i = 0; i < scene.meshes.size(); ++i) {
    Mesh& mesh = scene.meshes[i];
    if (scene.shapes[i].kind != ShapeKind::Custom || std::isinf(errors[i]) || mesh.indices.empty())
      continue;
    stats.trianglesBefore += mesh.triangleCount();
    // meshopt_simplify takes the error relative to the mesh's extent.
    float scale =
        meshopt_simplifyScale(&mesh.vertices[0].position.x, mesh.vertices.size(), sizeof(Vertex));
    float relative = std::min(errors[i] / std::max(scale, 1e-12f), 1.0f);
    std::vector<uint32_t> indices(mesh.indices.size());
    float achieved = 0.0f;
    size_t count = meshopt_simplify(indices.data(), mesh.indices.data(), mesh.indices.size(),
                                    &mesh.vertices[0].position.x, mesh.vertices.size(),
                                    sizeof(Vertex), 0, relative, 0, &achieved);
    if (count >= 3) {
      indices.resize(count);
      meshopt_optimizeVertexCache(indices.data(), indices.data(), count, mesh.vertices.size());
      size_t used =
          meshopt_optimizeVertexFetch(mesh.vertices.data(), indices.data(), count,
                                      mesh.vertices.data(), mesh.vertices.size(), sizeof(Vertex));
      mesh.vertices.resize(used);
      mesh.indices = std::move(indices);
    }
    stats.trianglesAfter += mesh.triangleCount();
  }
  return stats;
}

std::vector<MeshLevel> simplifiedLevels(const Mesh& mesh, uint32_t minTriangles) {
  std::vector<MeshLevel> levels;
  if (mesh.indices.empty() || mesh.vertices.empty()) return levels;
  // meshopt_simplify's errors are relative to the mesh's extent.
  float scale =
      meshopt_simplifyScale(&mesh.vertices[0].position.x, mesh.vertices.size(), sizeof(Vertex));
  const std::vector<uint32_t>* source = &mesh.indices;
  while (source->size() / 3 / 2 >= minTriangles) {
    size_t target = source->size() / 2 / 3 * 3;
    std::vector<uint32_t> indices(source->size());
    float relative = 0.0f;
    // Each level from the one before (cheaper than from the full mesh each
    // time); the error bound is 1, the whole extent: the count is the goal.
    size_t count = meshopt_simplify(indices.data(), source->data(), source->size(),
                                    &mesh.vertices[0].position.x, mesh.vertices.size(),
                                    sizeof(Vertex), target, 1.0f, 0, &relative);
    if (count < 3 || count * 10 > source->size() * 9) break;
    indices.resize(count);
    meshopt_optimizeVertexCache(indices.data(), indices.data(), count, mesh.vertices.size());
    // Errors add up along the chain (each level measured against the one before).
    float previous = levels.empty() ? 0.0f : levels.back().error;
    levels.push_back({std::move(indices), previous + relative * scale});
    source = &levels.back().indices;
  }
  return levels;
}

std::vector<ShapeLevel> tessellationLevels(const ShapeDesc& shape) {
  // The chord error of a circle of radius r in n segments.
  auto chord = [](float radius, uint32_t segments) {
    return radius * (1.0f - std::cos(kPi / float(segments)));
  };
  std::vector<ShapeLevel> levels;
  ShapeDesc level = shape;
  for (;;) {
    switch (shape.kind) {
      case ShapeKind::UvSphere:
      case ShapeKind::Torus:
        if (level.tessellation / 2 < 3) return levels;
        level.tessellation /= 2;
        break;
      case ShapeKind::Teapot:
        if (level.tessellation / 2 < 1) return levels;
        level.tessellation /= 2;
        break;
      case ShapeKind::Icosphere:
        if (level.tessellation == 0) return levels;
        level.tessellation -= 1;
        break;
      default:
        return levels;
    }
    float error = 0.0f;
    uint32_t n = level.tessellation;
    switch (shape.kind) {
      case ShapeKind::UvSphere:
        error = chord(shape.radius, n);
        break;
      case ShapeKind::Torus:  // the ring's outer circle, and the tube in n / 2
        error = std::max(chord(shape.majorRadius + shape.minorRadius, n),
                         chord(shape.minorRadius, std::max(3u, n / 2)));
        break;
      case ShapeKind::Teapot:  // the body of radius 2, four patches around
        error = chord(2.0f, 4 * n);
        break;
      default:  // icosphere: the sagitta of an edge, 1.107 rad at level 0
        error = shape.radius * (1.0f - std::cos(1.1071487f / float(1u << n) * 0.5f));
        break;
    }
    levels.push_back({level, error});
  }
}

uint32_t chooseLevel(std::span<const float> projectedErrors, uint32_t previous, float bound,
                     float hysteresis) {
  auto coarsestWithin = [&](float limit) {
    uint32_t level = 0;
    for (uint32_t i = 1; i < projectedErrors.size(); ++i)
      if (projectedErrors[i] <= limit) level = i;
    return level;
  };
  if (previous >= projectedErrors.size()) return coarsestWithin(bound);
  uint32_t coarser = coarsestWithin(hysteresis * bound);
  if (projectedErrors[previous] <= bound && previous >= coarser) return previous;
  return previous < coarser ? coarser : coarsestWithin(bound);
}

}  // namespace shadelab
