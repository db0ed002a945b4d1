#include "core/base/image_reader.h"

#include <cassert>
#include <cstring>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/png_codec.h"

namespace shadelab {

ImageReader::ImageReader(const std::filesystem::path& path, std::string prefix)
    : path_(path.string()), prefix_(std::move(prefix)) {
  // Eight bytes tell a PNG; only then is the whole file read here.
  std::string start;
  if (FILE* file = std::fopen(path_.c_str(), "rb")) {
    char signature[8];
    start.assign(signature, std::fread(signature, 1, sizeof signature, file));
    std::fclose(file);
  }
  if (hasPngSignature(start)) {
    pngBytes_ = readInputFile(path, "image", kMaxBinaryInputBytes);
    PngHeader png = readPngHeader(pngBytes_, prefix_);
    if (pngReadableHere(png)) {
      header_ = {int(png.width), int(png.height), int(png.channels), oiio::PixelType::UInt8};
      return;
    }
    pngBytes_.clear();
  }
  file_ = oiio::oiioModule("read '" + path_ + "'").openImage(path_);
  std::string error;
  if (!file_->readHeader(header_, error)) throw InputError(prefix_ + ": " + error);
}

ImageReader::~ImageReader() = default;

void ImageReader::read(oiio::PixelType as, int subimage) {
  assert(as == oiio::PixelType::UInt8 || as == oiio::PixelType::Float);
  if (file_) {
    std::string error;
    if (!file_->read(subimage, as, error)) throw InputError(prefix_ + ": " + error);
    header_ = file_->header();
    return;
  }
  if (subimage != 0) throw InputError(prefix_ + ": a PNG holds one image");
  PngHeader png;
  pngPixels_ = readPngPixels(pngBytes_, prefix_, png);
  pngBytes_ = std::string();
}

void ImageReader::getRows(int yBegin, int yEnd, oiio::PixelType as, void* out) const {
  if (file_) return file_->getRows(yBegin, yEnd, as, out);
  size_t rowValues = size_t(header_.width) * header_.channels;
  const uint8_t* from = pngPixels_.data() + size_t(yBegin) * rowValues;
  size_t count = size_t(yEnd - yBegin) * rowValues;
  if (as == oiio::PixelType::UInt8) {
    std::memcpy(out, from, count);
    return;
  }
  // OpenImageIO's conversion of 8-bit values to float: v * (1/255), not
  // v / 255 (they differ in the last bit for 126 of the 256 values).
  float* values = static_cast<float*>(out);
  for (size_t i = 0; i < count; ++i) values[i] = float(from[i]) * (1.0f / 255.0f);
}

}  // namespace shadelab
