#include "core/scene/environment.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/image_reader.h"
#include "core/scene/texture.h"

namespace shadelab {
namespace {

constexpr float kPi = 3.14159265358979f;

// Bilinear lookup at continuous texel coordinates, x wrapping or clamped, y clamped.
glm::vec3 bilinear(const ImageRgba& image, glm::vec2 uv, bool wrapX) {
  float x = uv.x * float(image.width) - 0.5f;
  float y = uv.y * float(image.height) - 0.5f;
  float x0 = std::floor(x), y0 = std::floor(y);
  glm::vec2 f(x - x0, y - y0);
  auto texel = [&](int tx, int ty) {
    int w = int(image.width), h = int(image.height);
    tx = wrapX ? ((tx % w) + w) % w : std::clamp(tx, 0, w - 1);
    ty = std::clamp(ty, 0, h - 1);
    return glm::vec3(image.at(uint32_t(tx), uint32_t(ty)));
  };
  int ix = int(x0), iy = int(y0);
  glm::vec3 top = glm::mix(texel(ix, iy), texel(ix + 1, iy), f.x);
  glm::vec3 bottom = glm::mix(texel(ix, iy + 1), texel(ix + 1, iy + 1), f.x);
  return glm::mix(top, bottom, f.y);
}

glm::vec3 rotateY(glm::vec3 d, float radians) {
  float c = std::cos(radians), s = std::sin(radians);
  return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

}  // namespace

bool SkyDesc::operator==(const SkyDesc& other) const {
  return zenith == other.zenith && horizon == other.horizon && ground == other.ground &&
         sunDirection == other.sunDirection && sunSizeDegrees == other.sunSizeDegrees &&
         sunIntensity == other.sunIntensity;
}

uint32_t cubeResolution(const Environment& environment) {
  switch (environment.kind) {
    case EnvironmentKind::CubeFaces:  // uploaded as they are, never resampled
      return environment.faces[0] ? environment.faces[0]->width : 1;
    case EnvironmentKind::Panorama: {
      if (environment.resolution > 0) return environment.resolution;
      uint32_t quarter = std::max(1u, (environment.panorama->width + 3) / 4);
      return std::clamp(std::bit_ceil(quarter), 64u, 2048u);
    }
    case EnvironmentKind::Sky:
      return environment.resolution > 0 ? environment.resolution : 512;
    case EnvironmentKind::None:
      return 1;
  }
  return 1;
}

glm::vec3 cubeFaceDirection(uint32_t face, glm::vec2 st) {
  glm::vec2 c = 2.0f * st - 1.0f;  // (sc, tc) / |ma|
  switch (face) {
    case 0:
      return {1.0f, -c.y, -c.x};  // +X: sc = -rz, tc = -ry
    case 1:
      return {-1.0f, -c.y, c.x};  // -X: sc = +rz, tc = -ry
    case 2:
      return {c.x, 1.0f, c.y};  // +Y: sc = +rx, tc = +rz
    case 3:
      return {c.x, -1.0f, -c.y};  // -Y: sc = +rx, tc = -rz
    case 4:
      return {c.x, -c.y, 1.0f};  // +Z: sc = +rx, tc = -ry
    default:
      return {-c.x, -c.y, -1.0f};  // -Z: sc = -rx, tc = -ry
  }
}

CubeCoordinate cubeCoordinate(glm::vec3 d) {
  glm::vec3 a = glm::abs(d);
  uint32_t face;
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x >= 0.0f ? 0 : 1;
    sc = d.x >= 0.0f ? -d.z : d.z, tc = -d.y, ma = a.x;
  } else if (a.y >= a.z) {
    face = d.y >= 0.0f ? 2 : 3;
    sc = d.x, tc = d.y >= 0.0f ? d.z : -d.z, ma = a.y;
  } else {
    face = d.z >= 0.0f ? 4 : 5;
    sc = d.z >= 0.0f ? d.x : -d.x, tc = -d.y, ma = a.z;
  }
  return {face, 0.5f * (glm::vec2(sc, tc) / ma + 1.0f)};
}

glm::vec2 equirectCoordinates(glm::vec3 d) {
  float length = glm::length(d);
  float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
  float v = std::acos(std::clamp(d.y / length, -1.0f, 1.0f)) / kPi;
  return {u, v};
}

glm::vec3 equirectDirection(glm::vec2 uv) {
  float longitude = (uv.x - 0.5f) * 2.0f * kPi;
  float polar = uv.y * kPi;
  float ring = std::sin(polar);
  return {ring * std::sin(longitude), std::cos(polar), -ring * std::cos(longitude)};
}

gpu::SkyParameters skyParameters(const SkyDesc& sky, float intensity, uint32_t faceSize) {
  gpu::SkyParameters parameters{};
  parameters.zenith = glm::vec4(intensity * sky.zenith, 0.0f);
  parameters.horizon = glm::vec4(intensity * sky.horizon, 0.0f);
  parameters.ground = glm::vec4(intensity * sky.ground, 0.0f);
  float radius = glm::radians(0.5f * sky.sunSizeDegrees);
  glm::vec3 toSun = -glm::normalize(sky.sunDirection);
  parameters.sunDirection = glm::vec4(toSun, std::cos(radius));
  // No sun: radiance 0 (the disc test below still needs an ordered edge).
  glm::vec3 sun = sky.sunSizeDegrees > 0.0f ? intensity * sky.sunIntensity : glm::vec3(0.0f);
  parameters.sunRadiance = glm::vec4(sun, std::cos(0.5f * radius));
  parameters.face = glm::ivec4(int(faceSize), 0, 0, 0);
  return parameters;
}

glm::vec3 skyRadiance(const gpu::SkyParameters& sky, glm::vec3 d) {
  float y = std::clamp(d.y, -1.0f, 1.0f);
  glm::vec3 base = y >= 0.0f
                       ? glm::mix(glm::vec3(sky.horizon), glm::vec3(sky.zenith), std::sqrt(y))
                       : glm::mix(glm::vec3(sky.horizon), glm::vec3(sky.ground), std::sqrt(-y));
  float cosine = glm::dot(d, glm::vec3(sky.sunDirection));
  float outer = sky.sunDirection.w, inner = sky.sunRadiance.w;
  // smoothstep(outer, inner, cosine), written out as GLSL defines it.
  float t = inner > outer ? std::clamp((cosine - outer) / (inner - outer), 0.0f, 1.0f) : 0.0f;
  float disc = t * t * (3.0f - 2.0f * t);
  return base + disc * glm::vec3(sky.sunRadiance);
}

glm::vec3 environmentRadiance(const Environment& environment, glm::vec3 direction) {
  glm::vec3 d = glm::normalize(direction);
  switch (environment.kind) {
    case EnvironmentKind::None:
      return glm::vec3(0.0f);
    case EnvironmentKind::Sky:
      return skyRadiance(skyParameters(environment.sky, environment.intensity, 1), d);
    case EnvironmentKind::Panorama: {
      glm::vec3 turned = rotateY(d, -glm::radians(environment.rotationDegrees));
      return environment.intensity *
             bilinear(*environment.panorama, equirectCoordinates(turned), true);
    }
    case EnvironmentKind::CubeFaces: {
      CubeCoordinate c = cubeCoordinate(d);
      return environment.intensity * bilinear(*environment.faces[c.face], c.st, false);
    }
  }
  return glm::vec3(0.0f);
}

ImageRgba readLinearImage(const std::filesystem::path& path) {
  std::error_code error;
  // Only a missing path is "missing": a FIFO or a device is named as one.
  if (!std::filesystem::exists(path, error))
    throw InputError("image '" + path.string() + "' does not exist");
  checkInputFile(path, "image", kMaxBinaryInputBytes);
  ImageReader source(path, "cannot read image '" + path.string() + "'");
  checkTextureSize("image '" + path.string() + "'", source.header().width, source.header().height);
  source.read(oiio::PixelType::Float);
  const oiio::ImageHeader& spec = source.header();
  // Integer files hold sRGB-encoded display values; float files hold radiance.
  bool encoded = !source.floatingPoint() && spec.stored != oiio::PixelType::Double;
  int channels = spec.channels;
  std::vector<float> raw(size_t(spec.width) * spec.height * channels);
  source.getRows(0, spec.height, oiio::PixelType::Float, raw.data());
  ImageRgba image(uint32_t(spec.width), uint32_t(spec.height));
  size_t nanTexels = 0;
  std::string first;
  for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p) {
    const float* in = &raw[p * channels];
    float rgb[3] = {in[0], channels >= 3 ? in[1] : in[0], channels >= 3 ? in[2] : in[0]};
    // NaN radiance has no value to light with: refused, not drawn black.
    // +inf (a sun some half-float files store so) clamps to 65504 below.
    if (std::any_of(rgb, rgb + 3, [](float v) { return std::isnan(v); }) && nanTexels++ == 0)
      first =
          std::to_string(p % size_t(spec.width)) + ", " + std::to_string(p / size_t(spec.width));
    for (int c = 0; c < 3; ++c) {
      float value = encoded ? srgbToLinear(rgb[c]) : rgb[c];
      // NaN, negative or beyond half float's range (the cube is RGBA16F) would poison filtering.
      image.pixels[p * 4 + c] = value > 0.0f ? std::min(value, 65504.0f) : 0.0f;
    }
    image.pixels[p * 4 + 3] = 1.0f;
  }
  if (nanTexels > 0)
    throw InputError("image '" + path.string() + "': " + std::to_string(nanTexels) +
                     " texel(s) NaN (the first at x, y = " + first + "); expected numbers");
  return image;
}

}  // namespace shadelab
