#include "core/scene/texture.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/image.h"
#include "core/base/image_reader.h"

namespace shadelab {

void checkTextureSize(const std::string& name, int64_t width, int64_t height) {
  if (width > kMaxTextureSide || height > kMaxTextureSide)
    throw InputError(name + ": " + std::to_string(width) + "x" + std::to_string(height) +
                     " texels, more than the " + std::to_string(kMaxTextureSide) +
                     " allowed on a side");
}

uint64_t sceneTexels(const Scene& scene) {
  uint64_t texels = 0;
  for (const Texture& texture : scene.textures) texels += uint64_t(texture.width) * texture.height;
  return texels;
}

void checkSceneTexels(const std::string& name, int64_t width, int64_t height,
                      uint64_t texelsBefore) {
  // Sides within kMaxTextureSide: the product and the sum stay far below 2^64.
  const uint64_t texels =
      uint64_t(std::max<int64_t>(width, 0)) * uint64_t(std::max<int64_t>(height, 0));
  if (texelsBefore + texels <= kMaxSceneTexels) return;
  throw InputError(name + ": " + std::to_string(width) + "x" + std::to_string(height) +
                   " texels would bring the scene's textures to " +
                   std::to_string(texelsBefore + texels) + " texels, more than the " +
                   std::to_string(kMaxSceneTexels) + " allowed (1 GiB of RGBA8)");
}

Texture loadTextureFile(const std::filesystem::path& path, TextureRole role,
                        uint64_t texelsBefore) {
  std::string name = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw InputError("texture file '" + name + "' does not exist");
  if (std::filesystem::is_directory(path, error))
    throw InputError("texture file '" + name + "' is a directory, expected an image");
  checkInputFile(path, "texture file", kMaxBinaryInputBytes);
  // 8-bit PNG through libpng, other formats through the OpenImageIO module.
  ImageReader source(path, "texture file '" + name + "' cannot be read as an image");
  // The header first: a 3.5 MB PNG may declare 16384x16384 texels.
  checkTextureSize(name, source.header().width, source.header().height);
  checkSceneTexels(name, source.header().width, source.header().height, texelsBefore);
  // Only floating-point files hold linear light; 8- and 16-bit files hold
  // encoded values already (sRGB colour, or raw data).
  bool linearLight = source.floatingPoint();
  // Memory per texel while loading: the file's buffer (1 B per channel for
  // 8-bit files, 4 B otherwise) plus 4 B of rgba8; on the device the RGBA8
  // mip chain takes 4 * 4/3 B. 8-bit files are read as bytes: the values are
  // the same, v / 255 * 255 rounds back to v.
  oiio::PixelType readAs = source.header().stored == oiio::PixelType::UInt8
                               ? oiio::PixelType::UInt8
                               : oiio::PixelType::Float;
  source.read(readAs);
  const oiio::ImageHeader& spec = source.header();
  if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0)
    throw InputError("texture file '" + name + "' holds no pixels");
  int channels = spec.channels;
  // Converted a row at a time (get_pixels gives bytes as v / 255), so the
  // only whole-image copies are the buffer read above and rgba8 below.
  std::vector<float> row(size_t(spec.width) * channels);

  Texture texture;
  texture.name = name;
  texture.width = uint32_t(spec.width);
  texture.height = uint32_t(spec.height);
  texture.srgb = role == TextureRole::Color;
  texture.rgba8.resize(size_t(texture.width) * texture.height * 4);
  auto quantize = [](float value) {
    return uint8_t(std::lround(std::clamp(std::isnan(value) ? 0.0f : value, 0.0f, 1.0f) * 255.0f));
  };
  // A float file's NaN texels have no colour to give: refused, not drawn as
  // black. Infinities saturate, as any value past 1 does (a sun stored as +inf).
  size_t nanTexels = 0;
  std::string first;
  for (size_t p = 0; p < size_t(texture.width) * texture.height; ++p) {
    size_t x = p % texture.width;
    if (x == 0) {
      int y = int(p / texture.width);
      source.getRows(y, y + 1, oiio::PixelType::Float, row.data());
    }
    const float* in = &row[x * channels];
    float rgba[4] = {in[0], channels >= 3 ? in[1] : in[0], channels >= 3 ? in[2] : in[0],
                     channels == 4 ? in[3] : (channels == 2 ? in[1] : 1.0f)};
    if (std::any_of(rgba, rgba + 4, [](float v) { return std::isnan(v); }) && nanTexels++ == 0)
      first = std::to_string(x) + ", " + std::to_string(p / texture.width);
    for (int c = 0; c < 4; ++c) {
      bool encode = c < 3 && linearLight && role == TextureRole::Color;
      texture.rgba8[p * 4 + c] = quantize(encode ? linearToSrgb(rgba[c]) : rgba[c]);
    }
  }
  if (nanTexels > 0)
    throw InputError("texture file '" + name + "': " + std::to_string(nanTexels) +
                     " texel(s) NaN (the first at x, y = " + first + "); expected numbers");
  return texture;
}

uint32_t mipLevelCount(uint32_t width, uint32_t height) {
  return uint32_t(std::bit_width(std::max({width, height, 1u})));
}

glm::uvec2 mipLevelSize(uint32_t width, uint32_t height, uint32_t level) {
  return {std::max(1u, width >> level), std::max(1u, height >> level)};
}

Texture solidTexture(glm::u8vec4 rgba, TextureRole role, const std::string& name) {
  return {name, 1, 1, {rgba.r, rgba.g, rgba.b, rgba.a}, role == TextureRole::Color};
}

}  // namespace shadelab
