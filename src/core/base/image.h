#pragma once
// Images on the CPU: linear RGBA floats as rendered, and the 8-bit sRGB
// form written to PNG. 8-bit PNG goes through libpng; other formats through
// the OpenImageIO module, loaded on first use (oiio_module.h).
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <vector>

namespace shadelab {

// Linear RGBA, 4 floats per pixel, row 0 at the top.
struct ImageRgba {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> pixels;

  ImageRgba() = default;
  ImageRgba(uint32_t w, uint32_t h) : width(w), height(h), pixels(size_t(w) * h * 4, 0.0f) {}
  glm::vec4 at(uint32_t x, uint32_t y) const;
  void set(uint32_t x, uint32_t y, glm::vec4 value);
};

// 8-bit RGBA, sRGB-encoded, row 0 at the top: what a PNG holds.
struct ImageU8 {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> pixels;

  ImageU8() = default;
  ImageU8(uint32_t w, uint32_t h) : width(w), height(h), pixels(size_t(w) * h * 4, 0) {}
  glm::u8vec4 at(uint32_t x, uint32_t y) const;
  void set(uint32_t x, uint32_t y, glm::u8vec4 value);
};

// Pixel columns [left, left + width) of `image`, every row.
ImageU8 cropColumns(const ImageU8& image, uint32_t left, uint32_t width);

// The sRGB transfer functions (IEC 61966-2-1).
float linearToSrgb(float linear);
float srgbToLinear(float encoded);
// linearToSrgb clamped to [0, 1], times 255, rounded to nearest (NaN: 0),
// from a table: exactly that value, about ten times faster.
uint8_t linearToSrgb8(float linear);
// linearToSrgb8 per colour channel; alpha is stored linearly.
ImageU8 encodeSrgb8(const ImageRgba& image);
// encodeSrgb8 of RGBA half floats (IEEE binary16, 4 per pixel, rows packed):
// the same codes as encodeSrgb8 of the floats they hold, through two tables
// of all 65,536 halves, without the float image in between.
ImageU8 encodeSrgb8FromHalf(const uint16_t* rgba, uint32_t width, uint32_t height);

// Output formats by extension: .png (8-bit sRGB) or .exr (16-bit float, linear).
bool isSupportedOutput(const std::filesystem::path& path);
// Whether `path` names a linear (.exr, any case) rather than an 8-bit output.
bool isLinearOutput(const std::filesystem::path& path);
// Throws InputError unless `path` can be written: supported extension,
// existing parent folder. Call before rendering so bad paths fail fast.
void checkOutputPath(const std::filesystem::path& path);
// Writes atomically: a temporary file in the same folder, then a rename, so a
// failure never leaves a partial file. Throws InputError on failure.
void writeImage(const ImageRgba& image, const std::filesystem::path& path);
void writeImage(const ImageU8& image, const std::filesystem::path& path);
// An animated GIF of `frames` (all one size) at `framesPerSecond`, looping,
// through OpenImageIO's GIF writer (giflib; 256 colours per frame). Written
// atomically like writeImage. Throws InputError.
void writeAnimatedGif(const std::vector<ImageU8>& frames, const std::filesystem::path& path,
                      int framesPerSecond);
// Reads any format OpenImageIO knows into 8-bit sRGB RGBA. Throws InputError.
ImageU8 readImageU8(const std::filesystem::path& path);

}  // namespace shadelab
