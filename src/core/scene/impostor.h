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
#include <array>
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
// Whether an object placed by `transform` gets an impostor: a rotation and
// one positive scale (axes of equal length, at right angles, within 1e-4
// relative). The atlas holds the mesh's own views: a mirroring transform
// would need them reversed (and the mesh it draws is wound for the mirror,
// so it would capture inside out), and the blend of cells (impostorBlend)
// turns and scales its quad by one rotation and one scale. Other objects
// keep chains of meshes.
bool impostorTransformUsable(const glm::mat4& transform);

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

// The cells a view direction is drawn from, blended (billboard.frag): the
// three cells whose centres make the triangle of the cell grid that the
// direction's octahedral point falls in, weighted by its barycentric
// coordinates there. The weights are at least 0 and sum to 1; a direction at
// a cell's centre takes that cell alone, and they change continuously with
// the direction, so a turning view cross-fades between cells instead of
// jumping. Past the centres of the outermost cells (views from below, by
// the octahedral map's outer edge) the grid is clamped.
struct ImpostorBlend {
  std::array<ImpostorCell, 3> cells;
  std::array<float, 3> weights;
};
ImpostorBlend impostorBlend(glm::vec3 direction, uint32_t cells);

// The largest angle, in radians, between any direction and the direction of
// the cell it falls in (measured over a grid 16 times finer than the cells,
// corners included): 54.7 degrees for 4 cells, 15.1 for 16, 7.6 for 32.
float impostorParallaxAngle(uint32_t cells);
// The same for the blend: the largest, over all directions, of the weighted
// mean of the angles between the direction and its three cells'
// directions. 54.7 degrees for 4 cells, 14.6 for 16, 7.5 for 32: never more
// than impostorParallaxAngle at these counts.
float impostorBlendAngle(uint32_t cells);

// What an impostor of an object whose points lie within `radius` of the
// atlas centre can be off by, in the object's units: a cell's image puts a
// point h in front of or behind its plane on the plane, h along the
// captured direction from where it is; seen an angle away from that
// direction the two are h sin(angle) apart on the screen, at most radius
// sin(angle) (the blend weighs its cells' images: its point lies on average
// that far away, at its angle); plus half a texel of a cell. The larger of
// the two angles, so that the bound holds drawn either way. The level-of-detail chain ranks
// the impostor by it.
float impostorError(float radius, uint32_t cells, uint32_t cellTexels);

// Half the side of the square a cell's view covers, in object units: the
// radius plus the cell's margin.
float impostorHalfSize(float radius, uint32_t cellTexels);

}  // namespace shadelab
