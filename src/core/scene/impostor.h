#pragma once
// Octahedral impostors: an object seen from far enough away is drawn as one
// quad whose texture is the object as shadelab itself rendered it (albedo,
// coverage and normals) from the nearest of cells x cells directions spread
// over the whole sphere by the octahedral map. These are the geometry of it;
// the capture is passes/impostor_capture.h, the drawing the billboard pass.
//
// Object space, y up: a direction d maps to the octahedron |x|+|y|+|z| = 1
// and from there to [-1, 1]^2 by (x, z) on the upper half, the lower half
// folded out to the corners. Cell (column, row) covers [-1 + 2 column / n,
// -1 + 2 (column + 1) / n] of the first coordinate, rows the second; its
// direction is the one at its centre. With an even n no centre lies on the
// y axis, so every cell has a well-defined frame (right = y x d).
#include <cstdint>
#include <glm/glm.hpp>

#include "core/scene/mesh.h"

namespace shadelab {

// The cells per side an atlas has when nothing else is asked, and the texels
// per side of each cell. With 16 x 16 directions no view direction is more
// than 15.1 degrees from its cell's (impostorParallaxAngle: the octahedral
// map stretches the cells at the folds; 4 cells 54.7, 32 cells 7.6); 32
// texels suit an impostor drawn up to about 32 pixels across, which the
// error bound keeps it under.
inline constexpr uint32_t kImpostorCells = 16;
inline constexpr uint32_t kImpostorCellTexels = 32;
// Texels of empty margin on each side of a cell, so that filtering and the
// first mip levels do not pull in the neighbouring cells' pixels.
inline constexpr uint32_t kImpostorCellMargin = 2;

// The sphere an atlas is captured around, in the mesh's units: the centre of
// its box and the distance from there to its farthest vertex.
struct ImpostorSphere {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};
ImpostorSphere impostorSphere(const Mesh& mesh);
// Whether a mesh of this radius gets an impostor: finite and above 0. The
// capture divides by it. impostorSphere's lengths square the coordinates,
// so a mesh collapsed below about 1e-22 comes out as 0 and one beyond about
// 1.8e19 as infinite (NaN stays NaN): those keep chains of meshes.
bool impostorRadiusUsable(float radius);

glm::vec2 octahedralEncode(glm::vec3 direction);  // unit direction -> [-1, 1]^2
glm::vec3 octahedralDecode(glm::vec2 point);      // [-1, 1]^2 -> unit direction

struct ImpostorCell {
  uint32_t column = 0;
  uint32_t row = 0;
  uint32_t index(uint32_t cells) const { return row * cells + column; }
};
// The cell a unit direction falls in.
ImpostorCell impostorCell(glm::vec3 direction, uint32_t cells);
// The direction at a cell's centre (towards the viewer, from the object).
glm::vec3 impostorCellDirection(ImpostorCell cell, uint32_t cells);

// The capture's image axes for a view from `direction` (unit, towards the
// viewer): right = normalize(y x direction), up = direction x right. The
// atlas stores normals in this frame, which is also the quad's tangent frame.
struct ImpostorFrame {
  glm::vec3 right;
  glm::vec3 up;
};
ImpostorFrame impostorFrame(glm::vec3 direction);

// The largest angle, in radians, between any direction and the direction of
// the cell it falls in (measured over a grid 16 times finer than the cells,
// corners included).
float impostorParallaxAngle(uint32_t cells);

// What an impostor of an object whose points lie within `radius` of the
// atlas centre can be off by, in the object's units: the image puts a point
// h in front of or behind the quad on the quad, h along the captured
// direction from where it is; seen up to the parallax angle away from that
// direction the two are h sin(angle) apart on the screen, at most radius
// sin(angle); plus half a texel of a cell. The level-of-detail chain ranks
// the impostor by it.
float impostorError(float radius, uint32_t cells, uint32_t cellTexels);

// Half the side of the square a cell's view covers, in object units: the
// radius plus the cell's margin.
float impostorHalfSize(float radius, uint32_t cellTexels);

}  // namespace shadelab
