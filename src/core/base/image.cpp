#include "core/base/image.h"

#include <stdlib.h>  // mkdtemp

#include <algorithm>
#include <bit>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <glm/gtc/packing.hpp>
#include <limits>
#include <memory>
#include <system_error>
#include <vector>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/image_reader.h"
#include "core/base/oiio_module.h"
#include "core/base/png_codec.h"

namespace shadelab {
namespace fs = std::filesystem;

glm::vec4 ImageRgba::at(uint32_t x, uint32_t y) const {
  const float* p = &pixels[(size_t(y) * width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

void ImageRgba::set(uint32_t x, uint32_t y, glm::vec4 value) {
  float* p = &pixels[(size_t(y) * width + x) * 4];
  p[0] = value.r, p[1] = value.g, p[2] = value.b, p[3] = value.a;
}

glm::u8vec4 ImageU8::at(uint32_t x, uint32_t y) const {
  const uint8_t* p = &pixels[(size_t(y) * width + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

void ImageU8::set(uint32_t x, uint32_t y, glm::u8vec4 value) {
  uint8_t* p = &pixels[(size_t(y) * width + x) * 4];
  p[0] = value.r, p[1] = value.g, p[2] = value.b, p[3] = value.a;
}

ImageU8 cropColumns(const ImageU8& image, uint32_t left, uint32_t width) {
  assert(left + width <= image.width);
  ImageU8 part(width, image.height);
  for (uint32_t y = 0; y < image.height; ++y)
    std::copy_n(&image.pixels[(size_t(y) * image.width + left) * 4], size_t(width) * 4,
                &part.pixels[size_t(y) * width * 4]);
  return part;
}

float linearToSrgb(float linear) {
  if (!(linear > 0.0f)) return 0.0f;  // also maps NaN to 0
  if (linear >= 1.0f) return 1.0f;
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

namespace {

uint8_t quantize(float v) {
  return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// linearToSrgb8 without a pow per value: the floats in [2^-14, 1) in buckets
// of 4096 consecutive bit patterns (the exponent and the mantissa's top 11
// bits), each with the code at its start and the first float, if any, where
// the code steps up by one. The code steps at most once per bucket: a
// bucket spans 2^-11 of its start, and the steepest stretch of the curve
// (near 0.0031308) climbs 0.005 codes over that. The table is built from
// quantize(linearToSrgb(x)) itself, so it returns exactly that for every
// float (tests/test_metrics.cpp checks floats around every step; an
// exhaustive check of all 2^30 floats in [0, 1] found no difference).
class Srgb8Table {
 public:
  static constexpr uint32_t kFirst = 113u << 23;  // the bits of 2^-14: below it, code 0
  static constexpr uint32_t kOne = 127u << 23;    // the bits of 1.0f
  static constexpr int kBucketBits = 12;

  Srgb8Table() : buckets_((kOne - kFirst) >> kBucketBits) {
    auto code = [](uint32_t bits) { return quantize(linearToSrgb(std::bit_cast<float>(bits))); };
    assert(code(kFirst - 1) == 0);
    uint8_t low = code(kFirst);
    for (size_t i = 0; i < buckets_.size(); ++i) {
      uint32_t begin = kFirst + (uint32_t(i) << kBucketBits);
      uint32_t end = begin + (1u << kBucketBits);
      uint8_t high = code(end);
      assert(high - low <= 1);
      Bucket& bucket = buckets_[i];
      bucket.below = low;
      bucket.step = std::numeric_limits<float>::infinity();
      if (high != low) {  // the first bits with code(bits) == high, in (begin, end]
        uint32_t lower = begin, upper = end;
        while (upper - lower > 1) {
          uint32_t middle = lower + (upper - lower) / 2;
          (code(middle) == high ? upper : lower) = middle;
        }
        bucket.step = std::bit_cast<float>(upper);
      }
      low = high;
    }
  }

  uint8_t operator()(float linear) const {
    if (!(linear > 0.0f)) return 0;  // also NaN
    if (linear >= 1.0f) return 255;
    uint32_t bits = std::bit_cast<uint32_t>(linear);
    if (bits < kFirst) return 0;
    const Bucket& bucket = buckets_[(bits - kFirst) >> kBucketBits];
    return uint8_t(bucket.below + (linear >= bucket.step ? 1 : 0));
  }

 private:
  struct Bucket {
    float step;     // the first float of the bucket with code below + 1 (infinity: none)
    uint8_t below;  // the code before it
  };
  std::vector<Bucket> buckets_;
};

}  // namespace

uint8_t linearToSrgb8(float linear) {
  static const Srgb8Table table;  // ~30,000 pows, well under a millisecond, once
  return table(linear);
}

ImageU8 encodeSrgb8(const ImageRgba& image) {
  ImageU8 result(image.width, image.height);
  for (size_t i = 0; i < result.pixels.size(); ++i) {
    bool alpha = i % 4 == 3;
    result.pixels[i] = alpha ? quantize(image.pixels[i]) : linearToSrgb8(image.pixels[i]);
  }
  return result;
}

ImageU8 encodeSrgb8FromHalf(const uint16_t* rgba, uint32_t width, uint32_t height) {
  struct Tables {
    std::vector<uint8_t> colour, alpha;
    Tables() : colour(65536), alpha(65536) {
      for (uint32_t bits = 0; bits < 65536; ++bits) {
        float value = glm::unpackHalf1x16(uint16_t(bits));
        colour[bits] = linearToSrgb8(value);
        alpha[bits] = quantize(value);
      }
    }
  };
  static const Tables tables;  // 65,536 table look-ups each, under a millisecond, once
  ImageU8 result(width, height);
  for (size_t i = 0; i < result.pixels.size(); i += 4) {
    result.pixels[i] = tables.colour[rgba[i]];
    result.pixels[i + 1] = tables.colour[rgba[i + 1]];
    result.pixels[i + 2] = tables.colour[rgba[i + 2]];
    result.pixels[i + 3] = tables.alpha[rgba[i + 3]];
  }
  return result;
}

namespace {

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

}  // namespace

bool isSupportedOutput(const fs::path& path) {
  return lowerExtension(path) == ".png" || isLinearOutput(path);
}

bool isLinearOutput(const fs::path& path) {
  return lowerExtension(path) == ".exr";
}

void checkOutputPath(const fs::path& path) {
  if (path.empty()) throw InputError("output path is empty");
  if (!isSupportedOutput(path))
    throw InputError("output '" + path.string() + "': unsupported extension '" +
                     path.extension().string() + "' (expected .png or .exr)");
  checkWritableFolder(path);
  // EXR needs the OpenImageIO module: load it now, so a missing one fails
  // before the work rather than after it.
  if (isLinearOutput(path)) oiio::oiioModule("write '" + path.string() + "'");
}

namespace {

// Encodes in memory through the OpenImageIO module, then hands the bytes to
// the one atomic writer.
void encodeWithModule(const fs::path& path, int width, int height, oiio::PixelType stored,
                      oiio::PixelType given, const void* pixels,
                      const std::vector<std::pair<std::string, std::string>>& attributes) {
  std::vector<unsigned char> bytes;
  std::string error;
  if (!oiio::oiioModule("write '" + path.string() + "'")
           .encode(path.string(), width, height, stored, given, pixels, attributes, bytes, error))
    throw InputError("cannot encode '" + path.string() + "': " + error);
  writeFileAtomically(path,
                      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace

void writeImage(const ImageU8& image, const fs::path& path) {
  checkOutputPath(path);
  if (isLinearOutput(path)) {  // 8-bit values as they are, as OpenImageIO converts them
    encodeWithModule(path, int(image.width), int(image.height), oiio::PixelType::UInt8,
                     oiio::PixelType::UInt8, image.pixels.data(), {{"oiio:ColorSpace", "sRGB"}});
    return;
  }
  writeFileAtomically(
      path, encodePngRgba8(image.width, image.height, image.pixels.data(), path.string()));
}

void writeImage(const ImageRgba& image, const fs::path& path) {
  checkOutputPath(path);
  if (!isLinearOutput(path)) return writeImage(encodeSrgb8(image), path);
  // Stored as half, like the render target. OpenImageIO stamps the current
  // time as the EXR capDate unless DateTime is given: a fixed (empty) one
  // keeps the file byte-identical run to run.
  encodeWithModule(path, int(image.width), int(image.height), oiio::PixelType::Half,
                   oiio::PixelType::Float, image.pixels.data(),
                   {{"oiio:ColorSpace", "Linear"}, {"DateTime", ""}});
}

void writeAnimatedGif(const std::vector<ImageU8>& frames, const fs::path& path,
                      int framesPerSecond) {
  checkWritableFolder(path);
  if (frames.empty()) throw InputError("cannot write '" + path.string() + "': no frames");
  std::vector<const uint8_t*> pixels;
  for (const ImageU8& frame : frames) {
    if (frame.width != frames[0].width || frame.height != frames[0].height)
      throw InputError("cannot write '" + path.string() + "': frames of different sizes");
    pixels.push_back(frame.pixels.data());
  }
  oiio::Module& module = oiio::oiioModule("write '" + path.string() + "'");
  // OpenImageIO's GIF writer encodes through giflib to a file, not to memory:
  // a private temporary, read back whole (every frame decodes) before its
  // bytes go through the one atomic writer, since giflib does not report a
  // write that failed (a full disk gave a truncated file and success).
  // The temporary lives in a folder of its own that mkdtemp made (a name no
  // one could predict, mode 0700): a fixed name in the shared /tmp could be
  // planted as a symbolic link to a file of the user's, which giflib would
  // then overwrite.
  std::string folder = (fs::temp_directory_path() / "shadelab-gif-XXXXXX").string();
  if (!::mkdtemp(folder.data()))
    throw InputError("cannot write '" + path.string() + "': no temporary folder for the encoder (" +
                     folder + ": " + std::generic_category().message(errno) + ")");
  struct RemovedAtExit {
    fs::path folder;
    ~RemovedAtExit() {
      std::error_code ignored;
      fs::remove_all(folder, ignored);
    }
  } scratchFolder{folder};
  fs::path scratch = scratchFolder.folder / "frames.gif";
  std::string error;
  if (!module.writeGif(scratch.string(), int(frames[0].width), int(frames[0].height), pixels,
                       framesPerSecond, error))
    throw InputError("cannot encode '" + path.string() + "': " + error);
  std::string bytes = readInputFile(scratch, "encoded GIF", kMaxBinaryInputBytes);
  std::unique_ptr<oiio::ImageFile> last = module.openImage(scratch.string());
  if (!last->read(int(frames.size()) - 1, oiio::PixelType::UInt8, error))
    throw InputError("cannot write '" + path.string() + "': the encoded GIF (" +
                     std::to_string(bytes.size()) + " bytes) does not hold all " +
                     std::to_string(frames.size()) + " frames (disk full or a file size limit?)");
  last.reset();
  writeFileAtomically(path, bytes);
}

ImageU8 readImageU8(const fs::path& path) {
  if (!fs::exists(path)) throw InputError("image '" + path.string() + "' does not exist");
  checkInputFile(path, "image", kMaxBinaryInputBytes);
  ImageReader source(path, "cannot read image '" + path.string() + "'");
  source.read(oiio::PixelType::UInt8);
  const oiio::ImageHeader& spec = source.header();
  ImageU8 image(uint32_t(spec.width), uint32_t(spec.height));
  // Missing channels: grey replicates, alpha defaults to opaque.
  int channels = spec.channels;
  std::vector<uint8_t> raw(size_t(spec.width) * spec.height * channels);
  source.getRows(0, spec.height, oiio::PixelType::UInt8, raw.data());
  for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p) {
    const uint8_t* in = &raw[p * channels];
    uint8_t* out = &image.pixels[p * 4];
    out[0] = in[0];
    out[1] = channels >= 3 ? in[1] : in[0];
    out[2] = channels >= 3 ? in[2] : in[0];
    out[3] = channels == 4 ? in[3] : (channels == 2 ? in[1] : 255);
  }
  return image;
}

}  // namespace shadelab
