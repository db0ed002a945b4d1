// encodedImageSize: the size a PNG or JPEG declares, read from its header,
// which the glTF loader checks before decoding an embedded image.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <vector>

#include "core/base/image.h"
#include "core/scene/encoded_image.h"

namespace shadelab {
namespace {

std::vector<uint8_t> fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>((std::istreambuf_iterator<char>(in)), {});
}

// A JPEG's start: SOI, an APP0 segment, a DQT-sized filler segment, fill
// bytes, then `frameMarker` declaring 1024 wide and 768 high.
std::vector<uint8_t> jpegHeader(uint8_t frameMarker) {
  // One list: GCC 12 warns (-Warray-bounds, a false positive) on growing
  // the vector by insert or resize.
  // clang-format off
  std::vector<uint8_t> bytes = {
      0xFF, 0xD8,                                                  // SOI
      0xFF, 0xE0, 0x00, 0x10, 'J', 'F', 'I', 'F', 0x00,            // APP0
      0x01, 0x01, 0x00, 0x00, 0x01, 0x00, 0x01, 0x00, 0x00,        // (APP0)
      0xFF, 0xDB, 0x00, 0x04, 0x00, 0x00,                          // a short DQT
      0xFF, 0xFF,                                                  // fill
      0xFF, frameMarker, 0x00, 0x11, 0x08, 0x03, 0x00, 0x04, 0x00, 0x03,  // SOFn
      0, 0, 0, 0, 0, 0, 0, 0, 0};                                  // the components
  // clang-format on
  return bytes;
}

TEST(EncodedImageSize, PngAgreesWithTheDecoder) {
  std::filesystem::path path = std::filesystem::path(SHADELAB_ASSET_DIR) / "textures/letter-f.png";
  std::vector<uint8_t> bytes = fileBytes(path);
  ImageU8 decoded = readImageU8(path);
  auto size = encodedImageSize(bytes.data(), bytes.size());
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, decoded.width);
  EXPECT_EQ(size->height, decoded.height);
}

TEST(EncodedImageSize, PngHeaderAloneDeclaresItsSize) {
  std::vector<uint8_t> bytes =
      fileBytes(std::filesystem::path(SHADELAB_TEST_DATA_DIR) / "bad/huge_16384.png");
  auto size = encodedImageSize(bytes.data(), 24);  // signature and IHDR up to the height
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 16384u);
  EXPECT_EQ(size->height, 16384u);
  EXPECT_FALSE(encodedImageSize(bytes.data(), 23).has_value());
}

TEST(EncodedImageSize, JpegFrameHeaderAfterOtherSegments) {
  for (uint8_t marker : {0xC0, 0xC1, 0xC2}) {  // baseline, extended, progressive
    std::vector<uint8_t> bytes = jpegHeader(marker);
    auto size = encodedImageSize(bytes.data(), bytes.size());
    ASSERT_TRUE(size.has_value()) << int(marker);
    EXPECT_EQ(size->width, 1024u);
    EXPECT_EQ(size->height, 768u);
  }
  // C4 is a Huffman table, not a frame: skipped, and nothing follows it.
  std::vector<uint8_t> huffman = jpegHeader(0xC4);
  EXPECT_FALSE(encodedImageSize(huffman.data(), huffman.size()).has_value());
}

TEST(EncodedImageSize, OtherOrCutShortBytesDeclareNothing) {
  std::vector<uint8_t> jpeg = jpegHeader(0xC0);
  for (size_t length = 0; length + 10 < jpeg.size(); ++length)  // cut inside the frame header
    EXPECT_FALSE(encodedImageSize(jpeg.data(), length).has_value()) << length;
  const uint8_t bmp[] = {'B', 'M', 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                         0,   0,   0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_FALSE(encodedImageSize(bmp, sizeof bmp).has_value());
  EXPECT_FALSE(encodedImageSize(nullptr, 0).has_value());
  // Start of scan before any frame header.
  const uint8_t scanFirst[] = {0xFF, 0xD8, 0xFF, 0xDA, 0x00, 0x08, 0, 0, 0, 0, 0, 0};
  EXPECT_FALSE(encodedImageSize(scanFirst, sizeof scanFirst).has_value());
}

}  // namespace
}  // namespace shadelab
