#include "passes/equirect_cube_pass.h"

namespace shadelab {

EquirectCubePass::EquirectCubePass(const Context& context)
    : kernel_(
          context, "equirect_to_cube.comp",
          {{BINDING_CUBE_TARGET, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT},
           {BINDING_PANORAMA, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
            VK_SHADER_STAGE_COMPUTE_BIT}},
          sizeof(gpu::PanoramaParameters)) {}

void EquirectCubePass::record(VkCommandBuffer cmd, VkImageView target, VkImageView panorama,
                              VkSampler sampler, const gpu::PanoramaParameters& parameters) const {
  VkDescriptorImageInfo targetInfo{VK_NULL_HANDLE, target, VK_IMAGE_LAYOUT_GENERAL};
  VkDescriptorImageInfo panoramaInfo{sampler, panorama, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET},
                                    {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
  writes[0].dstBinding = BINDING_CUBE_TARGET;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  writes[0].pImageInfo = &targetInfo;
  writes[1].dstBinding = BINDING_PANORAMA;
  writes[1].descriptorCount = 1;
  writes[1].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  writes[1].pImageInfo = &panoramaInfo;
  kernel_.update({writes[0], writes[1]});
  uint32_t groups =
      (uint32_t(parameters.face.x) + CUBE_BUILD_GROUP_SIZE - 1) / CUBE_BUILD_GROUP_SIZE;
  kernel_.dispatch(cmd, &parameters, groups, groups, 6);
}

}  // namespace shadelab
