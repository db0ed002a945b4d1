#pragma once
// S-mappings: texture coordinates from a vertex's object-space position (and,
// for the box, its normal), for meshes without UVs or materials that ask for
// them. Each is fitted to the mesh's bounding box B (centre c, size s):
//   planar       u = (x - Bmin.x) / s.x,  v = (y - Bmin.y) / s.y   (along -z onto xy)
//   cylindrical  u = 0.5 + atan2(x - c.x, z - c.z) / 2 pi,  v = (y - Bmin.y) / s.y   (axis y)
//   spherical    d = p - c: u = 0.5 + atan2(d.x, d.z) / 2 pi,  v = 0.5 + asin(d.y / |d|) / pi
//   box          the planar mapping along the normal's dominant axis, oriented so each
//                face reads unmirrored from outside (+x: u = (Bmax.z - z) / s.z, ...)
// A zero extent maps to 0.5. Cylindrical and spherical mappings have a seam at
// the -z side (u jumps from 1 to 0 inside the triangles that cross it) and the
// box mapping a seam where the dominant axis changes: the known cost of
// S-mappings on meshes whose vertices are shared across the seam.
#include <glm/glm.hpp>

#include "core/scene/mesh.h"
#include "core/scene/scene.h"

namespace shadelab {

glm::vec2 projectUv(UvProjection projection, glm::vec3 position, glm::vec3 normal,
                    const Bounds& bounds);
// Replaces every vertex's UV (UvProjection::Mesh keeps them) and recomputes
// the tangents from the new UVs.
void applyUvProjection(Mesh& mesh, UvProjection projection);
// The same with the bounds given: a coarser level of detail is projected
// with its full mesh's box, so its texture does not shift at a switch.
void applyUvProjection(Mesh& mesh, UvProjection projection, const Bounds& bounds);

}  // namespace shadelab
