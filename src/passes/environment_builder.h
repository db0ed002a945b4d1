#pragma once
// Turns a scene's Environment into the cube map the forward and skybox
// passes sample: RGBA16F, six faces in Vulkan's layer order, a full mip chain
// (mip_generation.h), sampled trilinearly with clamp-to-edge (Vulkan filters cube
// maps across face edges: seamless). Sky: sky_cube_pass; panorama:
// uploaded as a mip-mapped 2D texture, then equirect_cube_pass; cube faces:
// uploaded as they are. Load time only: build() submits and waits.
#include <array>

#include "core/base/image.h"
#include "core/scene/environment.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/context.h"
#include "core/vulkan/resources.h"
#include "passes/equirect_cube_pass.h"
#include "passes/mip_generation.h"
#include "passes/sky_cube_pass.h"

namespace shadelab {

struct EnvironmentCube {
  Image image;  // 6 layers, every level in ShaderRead use
  Sampler sampler;
  uint32_t faceSize() const { return image.desc().width; }
  uint32_t mipLevels() const { return image.desc().mipLevels; }
  explicit operator bool() const { return bool(image); }
};

class EnvironmentBuilder {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

  explicit EnvironmentBuilder(const Context& context);
  // Asserts environment.present().
  EnvironmentCube build(const Environment& environment) const;
  // A 1x1 black cube, bound when there is no environment (lavapipe crashes
  // on descriptors that were never written).
  EnvironmentCube placeholder() const;

 private:
  EnvironmentCube allocate(uint32_t faceSize, uint32_t mipLevels) const;
  void buildSky(const Environment& environment, const EnvironmentCube& cube) const;
  void buildFromPanorama(const Environment& environment, const EnvironmentCube& cube) const;
  void buildFromFaces(const Environment& environment, const EnvironmentCube& cube) const;
  // Levels 1.. from level 0 (in `level0Use`); every level ends in ShaderRead.
  void recordMips(VkCommandBuffer cmd, const Image& image, ImageUse level0Use) const;

  const Context& context_;
  SkyCubePass sky_;
  EquirectCubePass equirect_;
  MipGeneration mips_;
};

// One mip level's six faces read back to the host (tests, tools), in layer order.
std::array<ImageRgba, 6> readCubeLevel(const Context& context, const EnvironmentCube& cube,
                                       uint32_t level);

}  // namespace shadelab
