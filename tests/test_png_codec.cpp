// The libpng path (core/base/png_codec, ImageReader) against OpenImageIO,
// which it replaced for 8-bit PNG: written files byte for byte, decoded
// pixels value for value, over the PNG kinds a reader must expand.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/image.h"
#include "core/base/image_reader.h"
#include "core/base/oiio_module.h"
#include "core/base/png_codec.h"
#include "test_folder.h"

namespace fs = std::filesystem;
using shadelab::ImageReader;
using shadelab::oiio::PixelType;

namespace {

// A PNG written by libpng directly, so the test chooses every field.
struct PngKind {
  std::string name;
  int colorType;
  int bitDepth;
  bool interlaced = false;
  bool transparentEntry = false;  // a tRNS chunk
  int chunks = 0;                 // 0 none, 1 sRGB, 2 gAMA 1.0, 3 gAMA 0.45455
};

void writeTestPng(const fs::path& path, const PngKind& kind, int width, int height) {
  FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, file);
  png_set_IHDR(png, info, width, height, kind.bitDepth, kind.colorType,
               kind.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (kind.colorType == PNG_COLOR_TYPE_PALETTE) {
    std::vector<png_color> palette(16);
    for (int i = 0; i < 16; ++i)
      palette[i] = {png_byte(i * 17), png_byte(255 - i * 13), png_byte(i * 7 + 3)};
    png_set_PLTE(png, info, palette.data(), 16);
    if (kind.transparentEntry) {
      png_byte alphas[3] = {0, 128, 77};
      png_set_tRNS(png, info, alphas, 3, nullptr);
    }
  } else if (kind.transparentEntry) {
    png_color_16 key{};
    key.gray = 3, key.red = 10, key.green = 20, key.blue = 30;
    png_set_tRNS(png, info, nullptr, 0, &key);
  }
  if (kind.chunks == 1) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (kind.chunks == 2) png_set_gAMA(png, info, 1.0);
  if (kind.chunks == 3) png_set_gAMA(png, info, 0.45455);
  png_write_info(png, info);
  int channels = png_get_channels(png, info);
  size_t rowBytes = (size_t(width) * channels * kind.bitDepth + 7) / 8;
  std::vector<png_byte> pixels(rowBytes * height);
  uint32_t seed = 12345;
  for (png_byte& byte : pixels) {
    seed = seed * 1664525u + 1013904223u;
    byte = png_byte(seed >> 24);
  }
  if (kind.colorType == PNG_COLOR_TYPE_PALETTE)  // indices within the palette
    for (png_byte& byte : pixels) byte &= kind.bitDepth == 8 ? 0x0f : 0xff;
  if (kind.transparentEntry && kind.colorType == PNG_COLOR_TYPE_RGB && kind.bitDepth == 8)
    for (int x = 0; x < width; x += 3)
      pixels[x * 3] = 10, pixels[x * 3 + 1] = 20, pixels[x * 3 + 2] = 30;
  std::vector<png_bytep> rows(height);
  for (int y = 0; y < height; ++y) rows[y] = pixels.data() + y * rowBytes;
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
}

template <typename T>
std::vector<T> readWithOiio(const fs::path& path, OIIO::TypeDesc type, int& channels) {
  OIIO::ImageBuf buffer(path.string());
  EXPECT_TRUE(buffer.read(0, 0, true, type)) << buffer.geterror();
  const OIIO::ImageSpec& spec = buffer.spec();
  channels = spec.nchannels;
  std::vector<T> values(size_t(spec.width) * spec.height * spec.nchannels);
  buffer.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, spec.nchannels), type,
                    values.data());
  return values;
}

template <typename T>
std::vector<T> readWithReader(const fs::path& path, PixelType readAs, PixelType as) {
  ImageReader reader(path, "test");
  reader.read(readAs);
  const auto& header = reader.header();
  std::vector<T> values(size_t(header.width) * header.height * header.channels);
  reader.getRows(0, header.height, as, values.data());
  return values;
}

const std::vector<PngKind>& kinds() {
  static const std::vector<PngKind> list = {
      {"grey1", PNG_COLOR_TYPE_GRAY, 1},
      {"grey2", PNG_COLOR_TYPE_GRAY, 2},
      {"grey4", PNG_COLOR_TYPE_GRAY, 4},
      {"grey8", PNG_COLOR_TYPE_GRAY, 8},
      {"grey8_trns", PNG_COLOR_TYPE_GRAY, 8, false, true},
      {"grey_alpha8", PNG_COLOR_TYPE_GRAY_ALPHA, 8},
      {"rgb8", PNG_COLOR_TYPE_RGB, 8},
      {"rgb8_trns", PNG_COLOR_TYPE_RGB, 8, false, true},
      {"rgba8", PNG_COLOR_TYPE_RGB_ALPHA, 8},
      {"rgba8_interlaced", PNG_COLOR_TYPE_RGB_ALPHA, 8, true},
      {"rgba8_srgb", PNG_COLOR_TYPE_RGB_ALPHA, 8, false, false, 1},
      {"rgba8_gamma1", PNG_COLOR_TYPE_RGB_ALPHA, 8, false, false, 2},
      {"rgba8_gamma045", PNG_COLOR_TYPE_RGB_ALPHA, 8, false, false, 3},  // the module's
      {"rgb8_gamma045", PNG_COLOR_TYPE_RGB, 8, false, false, 3},
      {"palette4", PNG_COLOR_TYPE_PALETTE, 4},
      {"palette8_trns", PNG_COLOR_TYPE_PALETTE, 8, false, true},
      {"rgb16", PNG_COLOR_TYPE_RGB, 16},          // the module's
      {"rgba16", PNG_COLOR_TYPE_RGB_ALPHA, 16}};  // the module's
  return list;
}

}  // namespace

// Every kind decodes to OpenImageIO's values, as bytes and as floats.
TEST(PngCodec, DecodesAsOpenImageIoDid) {
  fs::path dir = shadelab::test::testFolder();
  for (const PngKind& kind : kinds()) {
    SCOPED_TRACE(kind.name);
    fs::path path = dir / (kind.name + ".png");
    writeTestPng(path, kind, 37, 11);
    int channels = 0;
    auto bytes = readWithOiio<uint8_t>(path, OIIO::TypeDesc::UINT8, channels);
    EXPECT_EQ(ImageReader(path, "test").header().channels, channels);
    EXPECT_EQ(readWithReader<uint8_t>(path, PixelType::UInt8, PixelType::UInt8), bytes);
    auto floats = readWithOiio<float>(path, OIIO::TypeDesc::FLOAT, channels);
    EXPECT_EQ(readWithReader<float>(path, PixelType::Float, PixelType::Float), floats);
    // The texture loader's way: bytes in memory, floats out.
    OIIO::ImageBuf buffer(path.string());
    ASSERT_TRUE(buffer.read(0, 0, true, OIIO::TypeDesc::UINT8));
    std::vector<float> fromBytes(floats.size());
    buffer.get_pixels(OIIO::ROI(0, 37, 0, 11, 0, 1, 0, channels), OIIO::TypeDesc::FLOAT,
                      fromBytes.data());
    EXPECT_EQ(readWithReader<float>(path, PixelType::UInt8, PixelType::Float), fromBytes);
  }
  fs::remove_all(dir);
}

// The PNG writer's file is the one OpenImageIO writes at the same zlib
// level (1; OpenImageIO's default is 6), byte for byte.
TEST(PngCodec, EncodesAsOpenImageIoDoesAtLevelOne) {
  const uint32_t width = 97, height = 31;
  std::vector<uint8_t> pixels(size_t(width) * height * 4);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t((i * 7 + i / 97 * 3) & 0xff);
  OIIO::ImageSpec spec(int(width), int(height), 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  spec.attribute("png:compressionLevel", 1);
  std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create("x.png");
  ASSERT_TRUE(output);
  std::vector<unsigned char> expected;
  OIIO::Filesystem::IOVecOutput memory(expected);
  ASSERT_TRUE(output->set_ioproxy(&memory) && output->open("x.png", spec) &&
              output->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && output->close());
  std::string actual = shadelab::encodePngRgba8(width, height, pixels.data(), "x.png");
  EXPECT_EQ(actual, std::string(expected.begin(), expected.end()));
}

// A PNG that is not one: the message names the file and libpng's reason.
TEST(PngCodec, TruncatedFileIsAnInputError) {
  fs::path dir = shadelab::test::testFolder();
  std::vector<uint8_t> pixels(8 * 8 * 4, 200);
  std::string bytes = shadelab::encodePngRgba8(8, 8, pixels.data(), "t.png");
  shadelab::writeFileAtomically(dir / "t.png", std::string_view(bytes).substr(0, 60));
  try {
    shadelab::readImageU8(dir / "t.png");
    ADD_FAILURE() << "no error";
  } catch (const shadelab::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot read image '" + (dir / "t.png").string()),
              std::string::npos)
        << error.what();
  }
  fs::remove_all(dir);
}

// Reading and writing 8-bit PNG never loads the OpenImageIO module (this
// suite runs in its own process: cmake/gtest_suites.cmake); reading an EXR does.
TEST(PngWithoutModule, PngReadAndWriteLeaveTheModuleUnloaded) {
  if (shadelab::oiio::oiioModuleLoaded())
    GTEST_SKIP()
        << "an earlier test in this process loaded the module; ctest runs this suite alone";
  fs::path dir = shadelab::test::testFolder();
  shadelab::ImageU8 image(5, 3);
  image.set(1, 1, {10, 20, 30, 255});
  shadelab::writeImage(image, dir / "a.png");
  EXPECT_EQ(shadelab::readImageU8(dir / "a.png").at(1, 1), glm::u8vec4(10, 20, 30, 255));
  EXPECT_FALSE(shadelab::oiio::oiioModuleLoaded());
  shadelab::ImageRgba linear(5, 3);
  shadelab::writeImage(linear, dir / "a.exr");
  EXPECT_TRUE(shadelab::oiio::oiioModuleLoaded());
  fs::remove_all(dir);
}
