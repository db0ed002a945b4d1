#include "core/base/image.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>
#include <system_error>

#include "core/base/errors.h"
#include "core/base/files.h"

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

ImageU8 encodeSrgb8(const ImageRgba& image) {
  ImageU8 result(image.width, image.height);
  auto quantize = [](float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (size_t i = 0; i < result.pixels.size(); ++i) {
    bool alpha = i % 4 == 3;
    result.pixels[i] = quantize(alpha ? image.pixels[i] : linearToSrgb(image.pixels[i]));
  }
  return result;
}

bool isSupportedOutput(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext == ".png" || ext == ".exr";
}

void checkOutputPath(const fs::path& path) {
  if (path.empty()) throw InputError("output path is empty");
  if (!isSupportedOutput(path))
    throw InputError("output '" + path.string() + "': unsupported extension '" +
                     path.extension().string() + "' (expected .png or .exr)");
  checkWritableFolder(path);
}

namespace {

// Encodes in memory (OpenImageIO's IOVecOutput), checking each step and
// OpenImageIO's own error state, then hands the bytes to the one atomic
// writer. `spec` holds the pixels' format as stored in the file.
void writeEncoded(const OIIO::ImageSpec& spec, OIIO::TypeDesc pixelType, const void* pixels,
                  const fs::path& path) {
  checkOutputPath(path);
  std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.string());
  if (!output) throw InputError("cannot write '" + path.string() + "': " + OIIO::geterror());
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  bool encoded = output->set_ioproxy(&memory) && output->open(path.string(), spec) &&
                 output->write_image(pixelType, pixels);
  encoded = output->close() && encoded;
  if (!encoded || output->has_error())
    throw InputError("cannot encode '" + path.string() + "': " + output->geterror());
  writeFileAtomically(path,
                      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace

void writeImage(const ImageU8& image, const fs::path& path) {
  OIIO::ImageSpec spec(int(image.width), int(image.height), 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  writeEncoded(spec, OIIO::TypeDesc::UINT8, image.pixels.data(), path);
}

void writeImage(const ImageRgba& image, const fs::path& path) {
  checkOutputPath(path);
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext != ".exr") return writeImage(encodeSrgb8(image), path);
  // Stored as half, like the render target.
  OIIO::ImageSpec spec(int(image.width), int(image.height), 4, OIIO::TypeDesc::HALF);
  spec.attribute("oiio:ColorSpace", "Linear");
  // OpenImageIO stamps the current time as the EXR capDate unless DateTime is
  // given: a fixed (empty) one keeps the file byte-identical run to run.
  spec.attribute("DateTime", "");
  writeEncoded(spec, OIIO::TypeDesc::FLOAT, image.pixels.data(), path);
}

void writeAnimatedGif(const std::vector<ImageU8>& frames, const fs::path& path,
                      int framesPerSecond) {
  checkWritableFolder(path);
  if (frames.empty()) throw InputError("cannot write '" + path.string() + "': no frames");
  std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create("gif");
  if (!output || !output->supports("multiimage"))
    throw InputError("cannot write '" + path.string() +
                     "': this OpenImageIO has no animated GIF writer");
  OIIO::ImageSpec spec(int(frames[0].width), int(frames[0].height), 4, OIIO::TypeDesc::UINT8);
  int rate[2] = {framesPerSecond, 1};
  spec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
  spec.attribute("gif:LoopCount", 0);  // for ever
  std::vector<OIIO::ImageSpec> specs(frames.size(), spec);
  // OpenImageIO's GIF writer encodes through giflib to a file, not to memory:
  // a private temporary, read back whole (every frame decodes) before its
  // bytes go through the one atomic writer, since giflib does not report a
  // write that failed (a full disk gave a truncated file and success).
  fs::path scratch = fs::temp_directory_path() /
                     ("shadelab-" + std::to_string(::getpid()) + "-" + path.filename().string());
  bool encoded = output->open(scratch.string(), int(specs.size()), specs.data());
  for (size_t i = 0; encoded && i < frames.size(); ++i) {
    if (frames[i].width != frames[0].width || frames[i].height != frames[0].height)
      throw InputError("cannot write '" + path.string() + "': frames of different sizes");
    encoded = (i == 0 || output->open(scratch.string(), spec, OIIO::ImageOutput::AppendSubimage)) &&
              output->write_image(OIIO::TypeDesc::UINT8, frames[i].pixels.data());
  }
  encoded = output->close() && encoded;
  std::error_code ignored;
  if (!encoded || output->has_error()) {
    fs::remove(scratch, ignored);
    throw InputError("cannot encode '" + path.string() + "': " + output->geterror());
  }
  std::string bytes;
  try {
    bytes = readInputFile(scratch, "encoded GIF", kMaxBinaryInputBytes);
    OIIO::ImageBuf last(scratch.string());
    if (!last.read(int(frames.size()) - 1, 0, true, OIIO::TypeDesc::UINT8))
      throw InputError("cannot write '" + path.string() + "': the encoded GIF (" +
                       std::to_string(bytes.size()) + " bytes) does not hold all " +
                       std::to_string(frames.size()) + " frames (disk full or a file size limit?)");
  } catch (...) {
    fs::remove(scratch, ignored);
    throw;
  }
  fs::remove(scratch, ignored);
  writeFileAtomically(path, bytes);
}

ImageU8 readImageU8(const fs::path& path) {
  if (!fs::exists(path)) throw InputError("image '" + path.string() + "' does not exist");
  checkInputFile(path, "image", kMaxBinaryInputBytes);
  OIIO::ImageBuf source(path.string());
  if (!source.read(0, 0, true, OIIO::TypeDesc::UINT8))
    throw InputError("cannot read image '" + path.string() + "': " + source.geterror());
  const OIIO::ImageSpec& spec = source.spec();
  ImageU8 image(uint32_t(spec.width), uint32_t(spec.height));
  // Missing channels: grey replicates, alpha defaults to opaque.
  int channels = spec.nchannels;
  std::vector<uint8_t> raw(size_t(spec.width) * spec.height * channels);
  source.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, channels),
                    OIIO::TypeDesc::UINT8, raw.data());
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
