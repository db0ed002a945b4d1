#include "core/scene/encoded_image.h"

#include <cstring>

namespace shadelab {
namespace {

uint32_t bigEndian32(const uint8_t* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}
uint32_t bigEndian16(const uint8_t* p) {
  return uint32_t(p[0]) << 8 | uint32_t(p[1]);
}

std::optional<EncodedImageSize> pngSize(const uint8_t* bytes, size_t size) {
  // Signature (8), then the IHDR chunk: length (4), "IHDR", width, height.
  static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 24 || std::memcmp(bytes, kSignature, 8) != 0 || std::memcmp(bytes + 12, "IHDR", 4))
    return std::nullopt;
  return EncodedImageSize{bigEndian32(bytes + 16), bigEndian32(bytes + 20)};
}

std::optional<EncodedImageSize> jpegSize(const uint8_t* bytes, size_t size) {
  if (size < 4 || bytes[0] != 0xFF || bytes[1] != 0xD8) return std::nullopt;
  size_t at = 2;
  while (at + 4 <= size) {
    if (bytes[at] != 0xFF) return std::nullopt;
    uint8_t marker = bytes[at + 1];
    if (marker == 0xFF) {  // fill byte before a marker
      ++at;
      continue;
    }
    // Markers without a length: TEM, RST0..7.
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
      at += 2;
      continue;
    }
    // Start of scan or end of image before a frame header: no size.
    if (marker == 0xDA || marker == 0xD9) return std::nullopt;
    uint32_t length = bigEndian16(bytes + at + 2);
    if (length < 2) return std::nullopt;
    // SOF0..SOF15 except DHT (C4), JPG (C8) and DAC (CC): length (2),
    // precision (1), height (2), width (2).
    if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) {
      if (at + 9 > size || length < 7) return std::nullopt;
      return EncodedImageSize{bigEndian16(bytes + at + 7), bigEndian16(bytes + at + 5)};
    }
    at += 2 + size_t(length);
  }
  return std::nullopt;
}

}  // namespace

std::optional<EncodedImageSize> encodedImageSize(const uint8_t* bytes, size_t size) {
  if (!bytes) return std::nullopt;
  if (auto png = pngSize(bytes, size)) return png;
  return jpegSize(bytes, size);
}

}  // namespace shadelab
