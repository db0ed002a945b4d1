#pragma once
// "Model no more than the scene needs": geometry detail chosen from how large
// it appears. Both functions take a screen-space error bound in pixels and
// turn it into a world-space length at each object's nearest point.
#include <cstdint>
#include <span>
#include <vector>

#include "core/scene/scene.h"

namespace shadelab {

// The view detail is chosen for: the scene's camera and the image size.
struct ViewSize {
  Camera camera;
  uint32_t width = 1280;
  uint32_t height = 720;
};

// Pixels one world unit covers at eye-space depth `depth` (> 0): perspective
// height / (2 depth tan(fovy / 2)); a frustum's height near / ((top - bottom)
// depth); orthographic height / (top - bottom) at any depth.
float pixelsPerUnit(const ViewSize& view, float depth);
// The same at the nearest point of a world-space sphere (clamped to the near
// plane), so no part of it is seen larger.
float pixelsPerUnitForSphere(const ViewSize& view, glm::vec3 centre, float radius);

// The chord error of a circle of radius r drawn with n segments is
// r (1 - cos(pi / n)); the smallest n >= 3 keeping it within maxError.
uint32_t segmentsForChordError(float radius, float maxError);

// --tess auto: each procedural shape's tessellation from its projected size,
// so the chord error stays within maxErrorPixels (spheres and tori by their
// circles, icospheres by their edges, the teapot by its body's radius 2 split
// into 4 patches around). Planes and boxes are exact and keep theirs. A mesh
// shared by several objects takes the finest any of them needs.
void tessellateForView(Scene& scene, const ViewSize& view, float maxErrorPixels);

struct SimplifyStats {
  uint64_t trianglesBefore = 0;  // of the meshes simplified, once each
  uint64_t trianglesAfter = 0;
};
// --simplify PX: every loaded (custom) mesh simplified by meshopt_simplify
// until its geometric error, projected at the object's nearest point, would
// exceed maxErrorPixels; then re-ordered for the vertex cache and fetch.
SimplifyStats simplifyForView(Scene& scene, const ViewSize& view, float maxErrorPixels);

// A level of a mesh's detail chain: a subset of its triangles over the same
// vertices (meshopt_simplify), and the geometric error that cost, in the
// mesh's own units.
struct MeshLevel {
  std::vector<uint32_t> indices;
  float error = 0.0f;
};
// The chain --lod auto draws from, built once at upload: each level aims at
// half the triangles of the one before, until a level would have fewer than
// `minTriangles` or simplification stops gaining (a level must drop at least
// a tenth of the previous one's triangles). Errors rise along the chain;
// the full mesh (level 0, error 0) is not included.
std::vector<MeshLevel> simplifiedLevels(const Mesh& mesh, uint32_t minTriangles = 256);

// The same for a procedural shape: the shape at half its tessellation, a
// quarter, ... down to the coarsest its kind allows (an icosphere one level
// fewer each time), each with its chord error against the true surface, in
// the shape's units (the bound --tess auto meets). Planes and boxes are
// exact and have no chain.
struct ShapeLevel {
  ShapeDesc shape;
  float error = 0.0f;
};
std::vector<ShapeLevel> tessellationLevels(const ShapeDesc& shape);

// The level to draw this frame from each level's error projected to pixels
// (level 0 first, the full mesh, 0), the level drawn last frame (`previous`;
// kNoLevel on the first) and the bound in pixels: never a level whose error
// exceeds the bound; the coarsest within it on a first frame; afterwards
// the previous level while it stays within the bound, and a coarser one only
// once its error is below `hysteresis` times the bound, so an object at the
// threshold does not switch back and forth. A hysteresis of 1 switches as
// soon as a level crosses the bound (study lod-popping measures both).
constexpr uint32_t kNoLevel = ~0u;
constexpr float kLodHysteresis = 0.75f;
uint32_t chooseLevel(std::span<const float> projectedErrors, uint32_t previous, float bound,
                     float hysteresis = kLodHysteresis);

}  // namespace shadelab
