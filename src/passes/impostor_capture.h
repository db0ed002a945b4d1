#pragma once
// Impostor capture: an object's full mesh rendered by shadelab from every
// direction of an octahedral atlas (core/scene/impostor.h), cells x cells
// orthographic views side by side in one image, each cellTexels on a side.
// Reads: the scene's vertex and index buffers (positions and normals), one
// draw's full index range.
// Writes: an atlas image of its own, read back to the host and split into
// the two textures the billboard pass draws an impostor with: coverage (a
// white diffuse map whose alpha the cut-out tests) and the normals in each
// cell's frame (a tangent-space normal map of the quad). Runs at upload,
// once per distinct mesh, never per frame.
#include <cstddef>
#include <glm/glm.hpp>

#include "core/scene/scene.h"
#include "core/vulkan/context.h"
#include "core/vulkan/gpu_scene.h"
#include "core/vulkan/resources.h"

namespace shadelab {

struct ImpostorTextures {
  Texture coverage;  // sRGB white, alpha 255 where the mesh covers the texel, else 0
  // Linear, rgb = (n + 1) / 2 in the cell's frame; a = the surface's height
  // h above the quad, (1 + 254 (0.5 + 0.5 h / halfSize)) / 255; uncovered
  // texels repeat their covered neighbours' (dilated ring by ring within
  // the cell), so mip levels average the mesh's normals, not the clear.
  Texture normals;
};

// Atlases one scene may have (each 512 x 512 x 2 textures with their mips,
// about 2.8 MB of device memory at the default size): meshes past the first
// this many distinct ones keep chains that end in meshes.
inline constexpr size_t kMaxImpostorAtlases = 64;

class ImpostorCapture {
 public:
  explicit ImpostorCapture(const Context& context);
  // The atlas of `draw`'s full mesh, whose points lie within `radius` (> 0)
  // of `centre` (object space), each cell seeing impostorHalfSize(radius,
  // cellTexels) on either side of the centre.
  ImpostorTextures capture(const GpuScene& scene, const DrawItem& draw, glm::vec3 centre,
                           float radius, uint32_t cells, uint32_t cellTexels) const;
  // Gives every draw with a detail chain one more, coarsest level: its
  // impostor (a DrawLevel whose `impostor` names an impostor billboard
  // appended to scene.billboards), for opaque, untextured, non-reflective
  // materials. One atlas per distinct mesh (GpuScene::impostorTextures; at
  // most kMaxImpostorAtlases), captured from the coarsest level of its
  // chain within half a texel; one billboard per atlas and material. Its error is impostorError's,
  // at least the chain's coarsest so errors still rise along the chain.
  void addImpostors(const Scene& source, GpuScene& scene, uint32_t cells,
                    uint32_t cellTexels) const;

 private:
  const Context& context_;
  PipelineLayout layout_;
  ShaderModule vertex_, fragment_;
  mutable Pipeline pipeline_;  // built at the first capture
};

}  // namespace shadelab
