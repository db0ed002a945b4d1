#include "passes/sky_cube_pass.h"

namespace shadelab {

SkyCubePass::SkyCubePass(const Context& context)
    : kernel_(
          context, "sky_cube.comp",
          {{BINDING_CUBE_TARGET, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT}},
          sizeof(gpu::SkyParameters)) {}

void SkyCubePass::record(VkCommandBuffer cmd, VkImageView target,
                         const gpu::SkyParameters& sky) const {
  VkDescriptorImageInfo image{VK_NULL_HANDLE, target, VK_IMAGE_LAYOUT_GENERAL};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstBinding = BINDING_CUBE_TARGET;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  write.pImageInfo = &image;
  kernel_.update({write});
  uint32_t groups = (uint32_t(sky.face.x) + CUBE_BUILD_GROUP_SIZE - 1) / CUBE_BUILD_GROUP_SIZE;
  kernel_.dispatch(cmd, &sky, groups, groups, 6);
}

}  // namespace shadelab
