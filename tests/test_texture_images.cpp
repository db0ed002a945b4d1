// Texture mapping and mipmapping on the device: goldens of mip-plane per
// filter with must-fail twins, and mipmapping measured against supersampled
// references. Figures are printed. Bump mapping: test_bump_images.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/scene/procedural_textures.h"
#include "core/scene/scene.h"
#include "core/scene/transform.h"
#include "gpu_test_support.h"

namespace shadelab::test {
namespace {

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;

RenderSettings settingsFor(uint32_t width, uint32_t height, std::optional<TextureFilter> filter,
                           ShadingModel model = ShadingModel::Phong) {
  RenderSettings settings{width, height, model};
  settings.textures.filterOverride = filter;
  return settings;
}

// The mean of each factor x factor block, in linear light.
ImageRgba boxDownsample(const ImageRgba& image, uint32_t factor) {
  ImageRgba out(image.width / factor, image.height / factor);
  for (uint32_t y = 0; y < out.height; ++y)
    for (uint32_t x = 0; x < out.width; ++x) {
      glm::vec4 sum(0.0f);
      for (uint32_t j = 0; j < factor; ++j)
        for (uint32_t i = 0; i < factor; ++i) sum += image.at(x * factor + i, y * factor + j);
      out.set(x, y, sum / float(factor * factor));
    }
  return out;
}

ImageU8 rows(const ImageU8& image, uint32_t first, uint32_t count) {
  ImageU8 out(image.width, count);
  std::copy_n(image.pixels.begin() + ptrdiff_t(size_t(first) * image.width * 4), out.pixels.size(),
              out.pixels.begin());
  return out;
}

// The first row (from the top) where the ground shows: the horizon.
uint32_t horizonRow(const ImageU8& image, glm::u8vec4 sky) {
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x)
      if (image.at(x, y) != sky) return y;
  return image.height;
}

using TextureImages = GpuTest;

struct FilterGolden {
  const char* name;
  TextureFilter filter;
};

class MipPlaneGolden : public GpuTest, public ::testing::WithParamInterface<FilterGolden> {};

TEST_P(MipPlaneGolden, MatchesGolden) {
  ImageU8 image =
      render(builtinScene("mip-plane"), settingsFor(kWidth, kHeight, GetParam().filter));
  EXPECT_TRUE(matchesGolden(std::string("mip-plane-") + GetParam().name, image));
}

INSTANTIATE_TEST_SUITE_P(Filters, MipPlaneGolden,
                         ::testing::Values(FilterGolden{"nearest", TextureFilter::Nearest},
                                           FilterGolden{"bilinear", TextureFilter::Bilinear},
                                           FilterGolden{"trilinear", TextureFilter::Trilinear}),
                         [](const auto& info) { return std::string(info.param.name); });

// Must-fail twins: the neighbouring filter, or checks 0.5% smaller, must be rejected.
TEST_F(TextureImages, MipPlaneComparisonRejectsTheWrongFilterOrTiling) {
  Scene scene = builtinScene("mip-plane");
  EXPECT_FALSE(matchesImage(loadGolden("mip-plane-trilinear"),
                            render(scene, settingsFor(kWidth, kHeight, TextureFilter::Bilinear))));
  EXPECT_FALSE(matchesImage(loadGolden("mip-plane-bilinear"),
                            render(scene, settingsFor(kWidth, kHeight, TextureFilter::Trilinear))));
  scene.objects[0].material.uvScale *= 1.005f;
  EXPECT_FALSE(matchesImage(loadGolden("mip-plane-nearest"),
                            render(scene, settingsFor(kWidth, kHeight, TextureFilter::Nearest))));
}

TEST_F(TextureImages, MipTintMatchesGoldenAndShowsSeveralLevels) {
  RenderSettings settings = settingsFor(kWidth, kHeight, std::nullopt);
  settings.textures.mipTint = true;
  ImageU8 image = render(builtinScene("mip-plane"), settings);
  EXPECT_TRUE(matchesGolden("mip-plane-tint", image));
  EXPECT_FALSE(matchesImage(loadGolden("mip-plane-trilinear"), image));
}

// The reference takes 64 point samples of the base level per pixel (the scene
// at 8x width and height, nearest filtering without mipmaps, box-averaged in
// linear light): what the pixel's footprint holds, up to 64 samples. With 16
// (4x) the reference itself still aliases near the horizon.
TEST_F(TextureImages, MipmappingBeatsNearestAgainstASupersampledReference) {
  Scene scene = builtinScene("mip-plane");
  ImageRgba supersampled =
      renderer()
          .renderToImage(scene, settingsFor(8 * kWidth, 8 * kHeight, TextureFilter::Nearest))
          .image;
  ImageU8 reference = encodeSrgb8(boxDownsample(supersampled, 8));
  auto error = [&](TextureFilter filter) {
    return compareImages(reference, render(scene, settingsFor(kWidth, kHeight, filter))).rmse;
  };
  double nearest = error(TextureFilter::Nearest);
  double bilinear = error(TextureFilter::Bilinear);
  double trilinear = error(TextureFilter::Trilinear);
  std::printf(
      "mip-plane %ux%u, RMSE against 64 spp of the base level: nearest %.2f, bilinear "
      "%.2f, trilinear %.2f (trilinear/nearest %.2f)\n",
      kWidth, kHeight, nearest, bilinear, trilinear, trilinear / nearest);
  EXPECT_LT(trilinear, 0.5 * nearest);
  EXPECT_LT(bilinear, 0.8 * nearest);
  EXPECT_LT(trilinear, bilinear);
}

// Anisotropic filtering can take tens of seconds per frame on llvmpipe at some
// angles (PLATFORM.md), so it is measured at 64x64 only, against 256 samples
// per pixel (1024x1024, box-averaged). Its gain is where the footprint is long
// and thin: the quarter of the frame below the horizon.
TEST_F(TextureImages, AnisotropicBeatsNearestAndTrilinearAtTinySize) {
  Scene scene = builtinScene("mip-plane");
  ImageRgba supersampled =
      renderer().renderToImage(scene, settingsFor(1024, 1024, TextureFilter::Nearest)).image;
  ImageU8 reference = encodeSrgb8(boxDownsample(supersampled, 16));
  glm::u8vec4 sky = reference.at(0, 0);
  uint32_t band = horizonRow(reference, sky);
  ASSERT_LT(band + 16, 64u);
  auto error = [&](TextureFilter filter, bool farBand) {
    ImageU8 image = render(scene, settingsFor(64, 64, filter));
    if (!farBand) return compareImages(reference, image).rmse;
    return compareImages(rows(reference, band, 16), rows(image, band, 16)).rmse;
  };
  double nearest = error(TextureFilter::Nearest, false);
  double trilinear = error(TextureFilter::Trilinear, false);
  double aniso = error(TextureFilter::Anisotropic, false);
  double trilinearFar = error(TextureFilter::Trilinear, true);
  double anisoFar = error(TextureFilter::Anisotropic, true);
  std::printf(
      "mip-plane 64x64, RMSE against 256 spp: nearest %.2f, trilinear %.2f, aniso(8x) "
      "%.2f; rows %u-%u below the horizon: trilinear %.2f, aniso %.2f\n",
      nearest, trilinear, aniso, band, band + 15, trilinearFar, anisoFar);
  EXPECT_LT(aniso, 0.5 * nearest);
  EXPECT_LT(anisoFar, 0.95 * trilinearFar);
}

}  // namespace
}  // namespace shadelab::test
