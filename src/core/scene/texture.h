#pragma once
// Textures on the CPU: reading image files into Texture and the size of
// their mip chains. Upload and mip generation are on the device
// (passes/scene_textures, passes/mip_generation).
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "core/scene/scene.h"

namespace shadelab {

enum class TextureRole {
  Color,  // sRGB-encoded texels, sampled through an _SRGB format
  Data,   // normal and height maps: the values themselves, linear
};

// Texture files and glTF images larger than this on a side are refused (not
// downsampled): 8192x8192 RGBA8 is 256 MiB, its device mip chain 341 MiB.
inline constexpr int64_t kMaxTextureSide = 8192;
// Throws InputError naming `name` and its size when a side exceeds the limit.
void checkTextureSize(const std::string& name, int64_t width, int64_t height);

// All of a scene's textures together, counted before each is decoded (its
// header's size): 2^28 texels is 1 GiB of RGBA8, 1.33 GiB on the device with
// mip chains. Four textures at the side limit fit; a file of forty does not.
inline constexpr uint64_t kMaxSceneTexels = uint64_t(1) << 28;
// The texels of the scene's textures so far.
uint64_t sceneTexels(const Scene& scene);
// Throws InputError naming `name` when its width x height added to
// `texelsBefore` would pass kMaxSceneTexels (sides already within the limit).
void checkSceneTexels(const std::string& name, int64_t width, int64_t height,
                      uint64_t texelsBefore);

// Reads PNG, JPEG, Radiance HDR, EXR (anything OpenImageIO reads) into 8-bit
// RGBA. 8-bit files keep their values; float files (linear light) are sRGB
// encoded for Color and clamped to 0..1 for Data. Grey replicates into RGB,
// missing alpha is opaque. Throws InputError naming the file.
// `texelsBefore`: the scene's texels so far, for checkSceneTexels.
Texture loadTextureFile(const std::filesystem::path& path, TextureRole role,
                        uint64_t texelsBefore = 0);

// floor(log2(max(width, height))) + 1: every level down to 1x1.
uint32_t mipLevelCount(uint32_t width, uint32_t height);
// Level `level`'s size: each axis halves, rounding down, never below 1.
glm::uvec2 mipLevelSize(uint32_t width, uint32_t height, uint32_t level);

// As a C string for printf (the table's names are literals).
inline const char* textureFilterName(TextureFilter filter) {
  return nameOf(kTextureFilterNames, filter).data();
}

// A 1x1 texture of one value: the dummy bound to a material's empty slots.
Texture solidTexture(glm::u8vec4 rgba, TextureRole role, const std::string& name);

}  // namespace shadelab
