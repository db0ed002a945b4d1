#include "core/scene/shape.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/scene/bezier.h"

namespace shadelab {
namespace {

uint32_t scaled(uint32_t base, float scale, uint32_t minimum) {
  return std::max(minimum, uint32_t(std::lround(float(base) * scale)));
}

// The shape with the normals its construction gives (exact for procedural
// surfaces, from the partial derivatives for Bezier patches).
Mesh buildExactShape(const ShapeDesc& shape, float scale) {
  switch (shape.kind) {
    case ShapeKind::Plane:
      return makePlane(shape.size, scaled(shape.tessellation, scale, 1));
    case ShapeKind::Box:
      return makeBox(shape.halfExtents);
    case ShapeKind::UvSphere: {
      uint32_t slices = scaled(shape.tessellation, scale, 3);
      return makeUvSphere(shape.radius, slices, std::max(2u, slices / 2));
    }
    case ShapeKind::Icosphere: {
      // Each level halves the edges: scale s adds log2(s) levels.
      int extra = int(std::lround(std::log2(std::max(scale, 1e-3f))));
      uint32_t level = uint32_t(std::clamp(int(shape.tessellation) + extra, 0, 7));
      return makeIcosphere(shape.radius, level);
    }
    case ShapeKind::Torus: {
      uint32_t major = scaled(shape.tessellation, scale, 3);
      return makeTorus(shape.majorRadius, shape.minorRadius, major, std::max(3u, major / 2));
    }
    case ShapeKind::Teapot:
      return tessellatePatches(utahTeapotPatches(), scaled(shape.tessellation, scale, 1));
    case ShapeKind::Custom:
      break;
  }
  assert(false && "custom shapes have no description to build from");
  return {};
}

}  // namespace

Mesh buildShape(const ShapeDesc& shape, float scale) {
  Mesh mesh = buildExactShape(shape, scale);
  if (shape.creaseAngleDegrees >= 0.0f) computeCreaseNormals(mesh, shape.creaseAngleDegrees);
  return mesh;
}

const char* shapeKindName(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Plane:
      return "plane";
    case ShapeKind::Box:
      return "box";
    case ShapeKind::UvSphere:
      return "sphere";
    case ShapeKind::Icosphere:
      return "icosphere";
    case ShapeKind::Torus:
      return "torus";
    case ShapeKind::Teapot:
      return "teapot";
    case ShapeKind::Custom:
      return "mesh";
  }
  return "?";
}

}  // namespace shadelab
