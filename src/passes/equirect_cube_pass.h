#pragma once
// Equirectangular panorama -> level 0 of a cube map
// (shaders/equirect_to_cube.comp): every cube texel samples the panorama
// along its own directions, so the faces meet without seams.
// Reads: `panorama` (a mip-mapped 2D texture in ComputeRead use, sampled
// with u repeating). Writes: `target`, a 2D-array view of the cube's level 0,
// in ComputeWrite use.
#include "core/vulkan/context.h"
#include "interface.h"
#include "passes/compute_kernel.h"

namespace shadelab {

class EquirectCubePass {
 public:
  explicit EquirectCubePass(const Context& context);
  // Load time only: rewrites the pass's descriptor set.
  void record(VkCommandBuffer cmd, VkImageView target, VkImageView panorama, VkSampler sampler,
              const gpu::PanoramaParameters& parameters) const;

 private:
  ComputeKernel kernel_;
};

}  // namespace shadelab
