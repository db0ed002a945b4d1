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

ShapeDesc scaledShape(const ShapeDesc& shape, float scale) {
  ShapeDesc scaledDesc = shape;
  switch (shape.kind) {
    case ShapeKind::Plane:
    case ShapeKind::Teapot:
      scaledDesc.tessellation = scaled(shape.tessellation, scale, 1);
      break;
    case ShapeKind::UvSphere:
    case ShapeKind::Torus:
      scaledDesc.tessellation = scaled(shape.tessellation, scale, 3);
      break;
    case ShapeKind::Icosphere: {
      int extra = int(std::lround(std::log2(std::max(scale, 1e-3f))));
      scaledDesc.tessellation = uint32_t(std::clamp(int(shape.tessellation) + extra, 0, 7));
      break;
    }
    case ShapeKind::Box:
    case ShapeKind::Custom:
      break;
  }
  return scaledDesc;
}

Mesh buildShape(const ShapeDesc& shape, float scale) {
  Mesh mesh = buildExactShape(shape, scale);
  if (shape.creaseAngleDegrees >= 0.0f) computeCreaseNormals(mesh, shape.creaseAngleDegrees);
  return mesh;
}

MeshSize estimateShape(const ShapeDesc& shape, float scale) {
  auto grid = [](uint64_t columns, uint64_t rows, uint64_t copies) {
    return MeshSize{copies * columns * rows * 2, copies * (columns + 1) * (rows + 1)};
  };
  MeshSize size;
  switch (shape.kind) {
    case ShapeKind::Plane: {
      uint64_t side = scaled(shape.tessellation, scale, 1);
      size = grid(side, side, 1);
      break;
    }
    case ShapeKind::Box:
      size = {12, 24};
      break;
    case ShapeKind::UvSphere: {
      // Rings of quads between the poles, a fan of triangles at each pole
      // (mesh_shapes.cpp makeUvSphere).
      uint64_t slices = scaled(shape.tessellation, scale, 3);
      uint64_t rings = std::max<uint64_t>(2, slices / 2) - 1;
      size = {2 * slices * rings, 2 * slices + rings * (slices + 1)};
      break;
    }
    case ShapeKind::Icosphere: {
      int extra = int(std::lround(std::log2(std::max(scale, 1e-3f))));
      uint64_t level = uint64_t(std::clamp(int(shape.tessellation) + extra, 0, 7));
      uint64_t triangles = uint64_t(20) << (2 * level);
      size = {triangles, triangles};  // shared vertices plus the seam's copies, rounded up
      break;
    }
    case ShapeKind::Torus: {
      uint64_t major = scaled(shape.tessellation, scale, 3);
      size = grid(major, std::max<uint64_t>(3, major / 2), 1);
      break;
    }
    case ShapeKind::Teapot: {
      uint64_t side = scaled(shape.tessellation, scale, 1);
      size = grid(side, side, utahTeapotPatches().size());
      break;
    }
    case ShapeKind::Custom:
      break;
  }
  // Crease normals split vertices where faces meet: at most three per triangle.
  if (shape.creaseAngleDegrees >= 0.0f) size.vertices = 3 * size.triangles;
  return size;
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
