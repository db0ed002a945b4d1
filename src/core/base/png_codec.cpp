#include "core/base/png_codec.h"

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include "core/base/errors.h"

namespace shadelab {
namespace {

// libpng reports errors by longjmp to the setjmp in the calling function;
// its message is kept here first. Functions that call setjmp hold no C++
// object whose destructor the jump would skip between setjmp and the calls.
struct PngError {
  char message[256] = "unknown libpng error";
};

void onError(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(error->message, sizeof error->message, "%s", message);
  png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), size);
}

struct MemoryInput {
  std::string_view bytes;
  size_t at = 0;
};

void readBytes(png_structp png, png_bytep data, png_size_t size) {
  auto* input = static_cast<MemoryInput*>(png_get_io_ptr(png));
  if (size > input->bytes.size() - input->at) png_error(png, "file is truncated");
  std::memcpy(data, input->bytes.data() + input->at, size);
  input->at += size;
}

// Sets up decoding up to png_read_update_info (with OpenImageIO's
// png_set_expand) and fills `header`. Returns false after a libpng error.
bool startReading(png_structp png, png_infop info, PngHeader& header) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  int sRgbIntent = 0;
  double gamma = 0.0;
  bool sRgb = png_get_sRGB(png, info, &sRgbIntent) != 0;
  bool gammaChunk = png_get_gAMA(png, info, &gamma) != 0;
  png_set_expand(png);
  // Interlaced files: png_read_image passes over the rows once per pass.
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  header.width = png_get_image_width(png, info);
  header.height = png_get_image_height(png, info);
  header.channels = png_get_channels(png, info);
  header.bitDepth = png_get_bit_depth(png, info);
  // OpenImageIO associates with gamma 1 for sRGB files and files without
  // gAMA, and with a rounded 1/gAMA otherwise (measured).
  bool alpha = header.channels == 2 || header.channels == 4;
  header.gammaAlpha = alpha && !sRgb && gammaChunk && gamma != 1.0;
  return true;
}

bool finishReading(png_structp png, std::vector<png_bytep>& rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  return true;
}

// The read and info structs, destroyed even when a constructor throws.
struct ReadStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ReadStructs() = default;
  ReadStructs(const ReadStructs&) = delete;
  ReadStructs& operator=(const ReadStructs&) = delete;
  ~ReadStructs() { png_destroy_read_struct(&png, &info, nullptr); }
};

class PngDecoder {
 public:
  // `name` starts every message ("cannot read image 'x.png'").
  PngDecoder(std::string_view bytes, const std::string& name) : input_{bytes}, name_(name) {
    if (!hasPngSignature(bytes)) throw InputError(name_ + ": not a PNG file");
    structs_.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error_, onError, onWarning);
    if (structs_.png) structs_.info = png_create_info_struct(structs_.png);
    if (!structs_.png || !structs_.info) throw InputError(name_ + ": out of memory for libpng");
    png_ = structs_.png, info_ = structs_.info;
    png_set_read_fn(png_, &input_, readBytes);
    if (!startReading(png_, info_, header_)) fail();
  }

  const PngHeader& header() const { return header_; }

  std::vector<uint8_t> pixels() {
    size_t rowBytes = png_get_rowbytes(png_, info_);
    std::vector<uint8_t> pixels(rowBytes * header_.height);
    std::vector<png_bytep> rows(header_.height);
    for (uint32_t y = 0; y < header_.height; ++y) rows[y] = pixels.data() + y * rowBytes;
    if (!finishReading(png_, rows)) fail();
    return pixels;
  }

 private:
  [[noreturn]] void fail() { throw InputError(name_ + ": " + error_.message); }

  MemoryInput input_;
  std::string name_;
  PngError error_;
  ReadStructs structs_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
  PngHeader header_;
};

bool encode(png_structp png, png_infop info, uint32_t width, uint32_t height,
            std::vector<png_bytep>& rows, png_text* text) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
  png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
  png_set_text(png, info, text, 1);
  // zlib level 1 with the default strategy, and every row through the Sub
  // filter. libpng's default tries all five filters on every row: on the
  // default scene at 1280x720 that took 3.5x as long for a file 7% larger;
  // over the 76 images of scripts/output_md5s.sh Sub writes 1% fewer bytes
  // in all in two thirds of the time (files grow up to 46% on bump-mapped
  // noise and constant colour). Level 1 rather than OpenImageIO's 6: the
  // default scene's image deflates in 9 ms instead of 31 (187 KB against
  // 111 KB); the 79 PNGs of docs/images and tests/golden in 157 ms instead
  // of 559 (3.71 MB against 2.69 MB). About 20 ms of the first PNG's ~230
  // (docs/PERFORMANCE.md, "Start-up").
  png_set_compression_level(png, 1);
  png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

bool hasPngSignature(std::string_view bytes) {
  return bytes.size() >= 8 &&
         png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) == 0;
}

std::string encodePngRgba8(uint32_t width, uint32_t height, const uint8_t* pixels,
                           const std::string& name) {
  // OpenImageIO takes pixels as associated alpha and writes PNG's
  // unassociated form: c * 255 / a in integers, capped, where 0 < a < 255.
  std::vector<uint8_t> unassociated;
  size_t count = size_t(width) * height * 4;
  for (size_t p = 3; p < count && unassociated.empty(); p += 4)
    if (pixels[p] != 255) unassociated.assign(pixels, pixels + count);
  for (size_t p = 0; p < unassociated.size(); p += 4) {
    unsigned alpha = unassociated[p + 3];
    if (alpha == 0) continue;
    for (int c = 0; c < 3; ++c)
      unassociated[p + c] = uint8_t(std::min(255u, unsigned(unassociated[p + c]) * 255u / alpha));
  }
  if (!unassociated.empty()) pixels = unassociated.data();
  PngError error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, onError, onWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::string bytes;
  std::vector<png_bytep> rows(height);
  for (uint32_t y = 0; y < height; ++y)
    rows[y] = const_cast<png_bytep>(pixels + size_t(y) * width * 4);
  char key[] = "oiio:ColorSpace", value[] = "sRGB";
  png_text text{};
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = key;
  text.text = value;
  bool encoded = false;
  if (png && info) {
    png_set_write_fn(png, &bytes, appendBytes, nullptr);
    encoded = encode(png, info, width, height, rows, &text);
  }
  png_destroy_write_struct(&png, &info);
  if (!encoded) throw InputError("cannot encode '" + name + "': " + error.message);
  return bytes;
}

PngHeader readPngHeader(std::string_view bytes, const std::string& name) {
  return PngDecoder(bytes, name).header();
}

std::vector<uint8_t> readPngPixels(std::string_view bytes, const std::string& name,
                                   PngHeader& header) {
  PngDecoder decoder(bytes, name);
  header = decoder.header();
  if (!pngReadableHere(header)) throw InputError(name + ": needs OpenImageIO");  // caller's bug
  std::vector<uint8_t> pixels = decoder.pixels();
  if (header.channels == 2 || header.channels == 4) {
    // OpenImageIO's association with gamma 1: integer c * a / 255, rounding down.
    uint32_t alpha = header.channels - 1;
    for (size_t p = 0; p < pixels.size(); p += header.channels)
      for (uint32_t c = 0; c < alpha; ++c)
        pixels[p + c] = uint8_t(unsigned(pixels[p + c]) * pixels[p + alpha] / 255u);
  }
  return pixels;
}

}  // namespace shadelab
