#pragma once
// The dimensions an encoded PNG or JPEG declares, read from its header
// without decoding: the glTF loader checks them against kMaxTextureSide
// before tinygltf decodes an embedded image (a 40-byte PNG may declare
// 16384x16384 texels, 1 GiB once decoded).
#include <cstddef>
#include <cstdint>
#include <optional>

namespace shadelab {

struct EncodedImageSize {
  uint32_t width = 0;
  uint32_t height = 0;
};

// The size in a PNG's IHDR or a JPEG's first SOF marker; nullopt when the
// bytes are neither, or the header is cut short.
std::optional<EncodedImageSize> encodedImageSize(const uint8_t* bytes, size_t size);

}  // namespace shadelab
