#pragma once
// Procedural shapes as descriptions, so a scene can be rebuilt at another
// tessellation (the comparison reference uses 4x; `--tess` later).
#include <cstdint>
#include <glm/glm.hpp>

#include "core/scene/mesh.h"

namespace shadelab {

enum class ShapeKind { Plane, Box, UvSphere, Icosphere, Torus, Teapot, Custom };

struct ShapeDesc {
  ShapeKind kind = ShapeKind::Custom;
  float size = 1.0f;            // plane: side length
  glm::vec3 halfExtents{0.5f};  // box
  float radius = 1.0f;          // uv sphere, icosphere
  float majorRadius = 1.0f;     // torus
  float minorRadius = 0.25f;    // torus
  // Base tessellation: plane quads per side, sphere slices (stacks = slices / 2),
  // icosphere subdivision level, torus major segments (minor = major / 2),
  // teapot quads per patch side. Boxes are exact and ignore it.
  uint32_t tessellation = 16;
  // Negative: keep the shape's exact normals. 0..180: replace them with
  // area-weighted averages, split wherever faces meet at more than this angle
  // (0 facets everything, 180 smooths everything, a box's edges are 90).
  float creaseAngleDegrees = -1.0f;
  // For an object whose transform mirrors (negative determinant): the mesh's
  // winding reversed (reverseWinding, core/scene/mesh.h) after it is built.
  bool mirrored = false;
};

// Builds the mesh at `scale` times the base tessellation (segments per side
// scale linearly; the icosphere level grows by log2(scale)). Custom shapes
// have no description to rebuild from: the caller keeps their mesh.
Mesh buildShape(const ShapeDesc& shape, float scale = 1.0f);
// The description buildShape(..., 1) builds exactly as buildShape(shape,
// scale): its tessellation scaled as buildShape scales it.
ShapeDesc scaledShape(const ShapeDesc& shape, float scale);
const char* shapeKindName(ShapeKind kind);

// What buildShape(shape, scale) will make, computed without building it, so
// a request can be refused before it allocates. Custom shapes: zero.
struct MeshSize {
  uint64_t triangles = 0;
  uint64_t vertices = 0;
  // Host bytes of the vertex and index arrays (48 B per vertex, 12 per triangle).
  uint64_t bytes() const { return vertices * 48 + triangles * 12; }
};
MeshSize estimateShape(const ShapeDesc& shape, float scale = 1.0f);

}  // namespace shadelab
