#pragma once
// One image file opened for reading, header first (so a size limit can be
// checked before the pixels are decoded). 8-bit PNG goes through libpng
// (png_codec.h); every other file (JPEG, HDR, EXR, TIFF, 16-bit PNG, ...)
// through the OpenImageIO module (oiio_module.h), loaded only then. Either
// way the pixels are what OpenImageIO's ImageBuf gave before the module
// existed (tests/test_png_codec.cpp compares them).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/base/oiio_module.h"

namespace shadelab {

class ImageReader {
 public:
  // Reads the file's header. Errors throw InputError starting with `prefix`
  // ("cannot read image 'x.png'") and then the reason. The file must already
  // have passed checkInputFile.
  ImageReader(const std::filesystem::path& path, std::string prefix);
  ~ImageReader();
  ImageReader(const ImageReader&) = delete;
  ImageReader& operator=(const ImageReader&) = delete;

  const oiio::ImageHeader& header() const { return header_; }
  bool floatingPoint() const {
    return header_.stored == oiio::PixelType::Float || header_.stored == oiio::PixelType::Half;
  }
  // Decodes subimage `subimage` into memory as `as` (UInt8 or Float). Throws.
  void read(oiio::PixelType as, int subimage = 0);
  // Rows [yBegin, yEnd) after read(), every channel, as `as` (UInt8 or Float).
  void getRows(int yBegin, int yEnd, oiio::PixelType as, void* out) const;

 private:
  std::string path_;
  std::string prefix_;
  oiio::ImageHeader header_;
  // libpng path: the file and its decoded, alpha-associated bytes.
  std::string pngBytes_;
  std::vector<uint8_t> pngPixels_;
  // OpenImageIO path.
  std::unique_ptr<oiio::ImageFile> file_;
};

}  // namespace shadelab
