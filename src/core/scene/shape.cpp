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
// surfaces, from the partial derivatives for Bezier patches), built at the
// description's own tessellation (scaledShape applies a factor first).
Mesh buildExactShape(const ShapeDesc& shape) {
  switch (shape.kind) {
    case ShapeKind::Plane:
      return makePlane(shape.size, shape.tessellation);
    case ShapeKind::Box:
      return makeBox(shape.halfExtents);
    case ShapeKind::UvSphere:
      return makeUvSphere(shape.radius, shape.tessellation, std::max(2u, shape.tessellation / 2));
    case ShapeKind::Icosphere:
      return makeIcosphere(shape.radius, shape.tessellation);
    case ShapeKind::Torus:
      return makeTorus(shape.majorRadius, shape.minorRadius, shape.tessellation,
                       std::max(3u, shape.tessellation / 2));
    case ShapeKind::Teapot:
      return tessellatePatches(utahTeapotPatches(), shape.tessellation);
    case ShapeKind::Custom:
      break;
  }
  assert(false && "custom shapes have no description to build from");
  return {};
}

}  // namespace

// The one place a factor becomes a tessellation: segments per side scale
// linearly (at least 1, or 3 around a circle), an icosphere gains log2 of
// the factor in levels (0..7).
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
  Mesh mesh = buildExactShape(scaledShape(shape, scale));
  if (shape.creaseAngleDegrees >= 0.0f) computeCreaseNormals(mesh, shape.creaseAngleDegrees);
  if (shape.mirrored) reverseWinding(mesh);
  return mesh;
}

MeshSize estimateShape(const ShapeDesc& shape, float scale) {
  auto grid = [](uint64_t columns, uint64_t rows, uint64_t copies) {
    return MeshSize{copies * columns * rows * 2, copies * (columns + 1) * (rows + 1)};
  };
  const uint64_t n = scaledShape(shape, scale).tessellation;  // what buildShape builds at
  MeshSize size;
  switch (shape.kind) {
    case ShapeKind::Plane:
      size = grid(n, n, 1);
      break;
    case ShapeKind::Box:
      size = {12, 24};
      break;
    case ShapeKind::UvSphere: {
      // Rings of quads between the poles, a fan of triangles at each pole
      // (mesh_shapes.cpp makeUvSphere).
      uint64_t rings = std::max<uint64_t>(2, n / 2) - 1;
      size = {2 * n * rings, 2 * n + rings * (n + 1)};
      break;
    }
    case ShapeKind::Icosphere: {
      uint64_t triangles = uint64_t(20) << (2 * n);
      size = {triangles, triangles};  // shared vertices plus the seam's copies, rounded up
      break;
    }
    case ShapeKind::Torus:
      size = grid(n, std::max<uint64_t>(3, n / 2), 1);
      break;
    case ShapeKind::Teapot:
      size = grid(n, n, utahTeapotPatches().size());
      break;
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
