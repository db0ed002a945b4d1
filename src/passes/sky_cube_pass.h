#pragma once
// Procedural sky -> level 0 of a cube map (shaders/sky_cube.comp, the sky of
// shaders/sky.glsl), one compute invocation per texel of each face.
// Reads: the sky parameters (push constants).
// Writes: `target`, a 2D-array view of the cube's level 0, in ComputeWrite use.
#include "core/vulkan/context.h"
#include "interface.h"
#include "passes/compute_kernel.h"

namespace shadelab {

class SkyCubePass {
 public:
  explicit SkyCubePass(const Context& context);
  // Load time only: rewrites the pass's descriptor set.
  void record(VkCommandBuffer cmd, VkImageView target, const gpu::SkyParameters& sky) const;

 private:
  ComputeKernel kernel_;
};

}  // namespace shadelab
