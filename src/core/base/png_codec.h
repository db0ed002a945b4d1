#pragma once
// 8-bit PNG through libpng: the default output and the common input, without
// loading OpenImageIO (oiio_module.h). Both directions reproduce what
// OpenImageIO 2.4 did, so decoded pixels stay bit-identical: the writer
// emits OpenImageIO's chunks (gAMA/sRGB/cHRM, oFFs, the "oiio:ColorSpace"
// text that tells OpenImageIO readers the file is sRGB) with its zlib level
// and strategy, and un-associates alpha as it did, but filters every row
// with Sub (png_codec.cpp says why); the reader expands palette, grey below
// 8 bits and tRNS like png_set_expand and associates alpha the way
// OpenImageIO's PNG reader does.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab {

// RGBA8 rows, top first, as a PNG file's bytes. Throws InputError naming
// `name` if libpng fails (it only can on memory exhaustion).
std::string encodePngRgba8(uint32_t width, uint32_t height, const uint8_t* pixels,
                           const std::string& name);

bool hasPngSignature(std::string_view bytes);

struct PngHeader {
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t channels = 0;  // after expansion: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA
  uint32_t bitDepth = 0;  // as stored: 8 after expansion, or 16
  // Alpha association needs a gamma other than 1 (a gAMA chunk without sRGB):
  // left to OpenImageIO rather than reproduced.
  bool gammaAlpha = false;
};

// The header of a PNG in memory. Throws InputError "<name>: <libpng's reason>".
PngHeader readPngHeader(std::string_view bytes, const std::string& name);
// Whether this reader takes the file: 8-bit (after expansion) and no gamma
// association. Others go to the OpenImageIO module.
inline bool pngReadableHere(const PngHeader& header) {
  return header.bitDepth == 8 && !header.gammaAlpha;
}
// The pixels, header.channels bytes each, alpha associated (premultiplied)
// as OpenImageIO does: c * a / 255 in integers. Throws InputError.
std::vector<uint8_t> readPngPixels(std::string_view bytes, const std::string& name,
                                   PngHeader& header);

}  // namespace shadelab
