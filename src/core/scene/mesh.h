#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace shadelab {

// Vertex layout shared with the GLSL vertex input (locations 0..3). 48 bytes, tightly packed.
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec4 tangent;  // xyz tangent along +u, w = handedness (+1/-1) so bitangent = w *
                      // cross(normal, tangent)
};

// The pipeline's vertex input description hard-codes these offsets, so a GLM configuration
// that pads or aligns its vector types must fail here rather than render garbage.
static_assert(sizeof(Vertex) == 48);
static_assert(offsetof(Vertex, position) == 0);
static_assert(offsetof(Vertex, normal) == 12);
static_assert(offsetof(Vertex, uv) == 24);
static_assert(offsetof(Vertex, tangent) == 32);

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise front faces seen from outside
  std::size_t triangleCount() const { return indices.size() / 3; }
};

// All shapes centred on the origin, right-handed, y up; counter-clockwise winding seen from outside
// (i.e. cross(b - a, c - a) points along the outward normal). UVs in [0,1], tangents from the UV
// parameterisation. Convention: +v runs along cross(normal, tangent), so every shape's mapping is
// unmirrored (w = +1) and a texture appears unflipped when viewed from outside with v pointing up.

// Texture coordinates of the unit direction from a sphere's centre, as the UV sphere and the
// icosphere lay them out (the ray tracer's exact spheres use it too).
glm::vec2 sphericalUv(glm::vec3 direction);

// In the XZ plane, normal +Y, u along +X, v along -Z; subdivisions >= 1 quads per side.
Mesh makePlane(float size, uint32_t subdivisions);
// 24 vertices (hard edges), 12 triangles.
Mesh makeBox(glm::vec3 halfExtents);
// slices >= 3, stacks >= 2; seam vertices duplicated at -Z; one vertex per slice at each pole, so
// the caps need no degenerate (zero-area) triangles.
Mesh makeUvSphere(float radius, uint32_t slices, uint32_t stacks);
// 20 * 4^subdivisions triangles, shared vertices (so the spherical UVs wrap across the seam);
// tangents from computeTangents.
Mesh makeIcosphere(float radius, uint32_t subdivisions);
// Around the Y axis; 0 < minorRadius < majorRadius, both segment counts >= 3.
Mesh makeTorus(float majorRadius, float minorRadius, uint32_t majorSegments,
               uint32_t minorSegments);

// Area-weighted vertex normals (sum of unnormalised face cross products), for meshes without
// normals. A zero-length result (isolated or degenerate-only vertex) becomes (0,1,0) rather than
// NaN.
void computeNormals(Mesh& mesh);

// Area-weighted vertex normals that keep hard edges: faces meeting at a vertex are smoothed
// together only if their normals differ by at most creaseAngleDegrees; otherwise the vertex is
// split (duplicated with the same position/uv) so each smooth group gets its own normal. 180
// smooths everything (same as computeNormals); 0 gives flat facets. Tangents are recomputed if the
// mesh had them. Vertices with identical positions are treated as one (a 24-vertex box can be
// smoothed). Each corner sums the faces at its position within the angle of its own face, without
// chaining through neighbours, so faces more than the angle apart never share a normal. Existing
// vertices are kept (first smooth group) and split ones are appended; zero-area triangles never
// cause a split.
void computeCreaseNormals(Mesh& mesh, float creaseAngleDegrees);

// Per-triangle tangents from positions and UVs (Lengyel's method), accumulated per vertex,
// Gram-Schmidt orthogonalised against the normal, handedness in w. Degenerate UVs give a tangent
// perpendicular to the normal (never NaN).
void computeTangents(Mesh& mesh);

Bounds computeBounds(const Mesh& mesh);

// Swaps each triangle's second and third index: counter-clockwise becomes
// clockwise. An object whose transform mirrors (negative determinant) turns
// its triangles' winding over, so it draws a mesh reversed this way; then
// the placed triangles wind counter-clockwise seen from outside, as back-face
// culling, flat shading's face normals and the ray tracer's expect (the glTF
// loader, ShapeDesc::mirrored). Normals and tangents stay: the normal matrix
// and the vertex stage's handedness sign already mirror them.
void reverseWinding(Mesh& mesh);

// Appends `other` to `mesh` with its indices offset (useful for building scenes).
void appendMesh(Mesh& mesh, const Mesh& other);

}  // namespace shadelab
