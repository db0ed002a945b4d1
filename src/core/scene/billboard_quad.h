#pragma once
// Where a billboard's copies stand for one camera: each copy's anchor and
// size, the axes its quad turns to, and the quads themselves as a world-space
// mesh. The billboard pass places its copies with billboardPlacement and
// billboardAxes (shaders/billboard.vert builds the corners the same way on
// the device); the ray tracer traces billboardQuads, so the reference sees
// the quads the rasterised frame of the same camera draws.
#include <glm/glm.hpp>

#include "core/scene/mesh.h"
#include "core/scene/scene.h"

namespace shadelab {

// One copy of a billboard, world space (a Billboard::instances matrix
// reduced to what a quad that faces the viewer keeps of it).
struct BillboardPlacement {
  glm::vec3 position{0.0f};  // the anchor point
  glm::vec2 size{1.0f};      // width, height
};

// The copy `instance` makes: its translation, and the billboard's size times
// the lengths of the matrix's x and y columns.
BillboardPlacement billboardPlacement(const Billboard& billboard, const glm::mat4& instance);

// Where the anchor sits on the quad's height: 0 at the bottom, 0.5 centred.
float anchorHeight(BillboardAnchor anchor);

// The quad's unit right and up in eye space for a copy whose anchor is at
// `anchor` (eye space) with `up` (eye space, unit: the billboard's axis
// turned by the view), as billboard.vert turns it. The quad's normal is
// cross(right, up): towards +z for a screen-aligned quad, towards the eye
// for a spherical one, and across the axis towards the eye for a
// cylindrical one.
struct BillboardAxes {
  glm::vec3 right{1.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
};
BillboardAxes billboardAxes(BillboardKind kind, glm::vec3 anchor, glm::vec3 up);

// Every copy's quad for the camera whose view matrix is `view`, in world
// space: four vertices (uv 0..1 across and up, the quad's normal, the
// tangent along its right) and two counter-clockwise triangles per copy,
// in the order of Billboard::instances.
Mesh billboardQuads(const Billboard& billboard, const glm::mat4& view);

}  // namespace shadelab
