#include "core/scene/scene_json_environment.h"

#include <bit>
#include <memory>
#include <string>

#include "core/base/errors.h"

namespace shadelab::scene_json {
namespace {

constexpr const char* kImageFile =
    "an image file (JPEG, PNG, HDR or EXR) relative to the scene file";

std::shared_ptr<const ImageRgba> readImage(const Field& field,
                                           const std::filesystem::path& folder) {
  if (!field.json().is_string()) field.wrongType(kImageFile);
  std::filesystem::path file = field.string();
  if (file.empty()) field.fail("empty file name", kImageFile);
  if (file.is_relative()) file = folder / file;
  try {
    return std::make_shared<const ImageRgba>(readLinearImage(file));
  } catch (const InputError& error) {
    field.fail(error.what(), kImageFile);
  }
}

uint32_t parseResolution(const Field& field) {
  uint32_t size = field.integer(16, 2048, "cube face size in texels");
  if (!std::has_single_bit(size))
    field.fail(std::to_string(size) + " is not a power of two",
               "a power of two from 16 to 2048 (the mip chain halves it down to 1)");
  return size;
}

SkyDesc parseSky(const Field& field) {
  SkyDesc sky;
  if (auto f = field.optional("zenith")) sky.zenith = f->colour();
  if (auto f = field.optional("horizon")) sky.horizon = f->colour();
  if (auto f = field.optional("ground")) sky.ground = f->colour();
  if (auto f = field.optional("sun_direction")) {
    sky.sunDirection = f->vec3();
    if (glm::length(sky.sunDirection) == 0.0f)
      f->fail("zero-length direction", "the direction sunlight travels, a non-zero vector");
  }
  if (auto f = field.optional("sun_size")) {
    sky.sunSizeDegrees = f->number();
    if (!(sky.sunSizeDegrees >= 0.0f && sky.sunSizeDegrees <= 90.0f))
      f->fail(formatNumber(sky.sunSizeDegrees) + " degrees is out of range",
              "the sun's angular diameter in degrees, 0 (no sun) to 90");
  }
  if (auto f = field.optional("sun_intensity")) {
    sky.sunIntensity = f->colour();
    if (glm::any(glm::greaterThan(sky.sunIntensity, glm::vec3(kMaxEnvironmentIntensity))))
      f->fail("a component above " + formatNumber(kMaxEnvironmentIntensity),
              "a number or 3 numbers from 0 to " + formatNumber(kMaxEnvironmentIntensity) +
                  " (radiance that large overflows the half-float target)");
  }
  return sky;
}

void parseFaces(const Field& field, const std::filesystem::path& folder, Environment& environment) {
  const char* expected = "an array of 6 image files in the order +x, -x, +y, -y, +z, -z";
  std::vector<Field> files = field.elements(expected);
  if (files.size() != 6) field.fail(std::to_string(files.size()) + " files", expected);
  for (size_t i = 0; i < 6; ++i) {
    environment.faces[i] = readImage(files[i], folder);
    const ImageRgba& face = *environment.faces[i];
    if (face.width != face.height)
      files[i].fail("the face is " + std::to_string(face.width) + "x" + std::to_string(face.height),
                    "a square image");
    const ImageRgba& first = *environment.faces[0];
    if (face.width != first.width)
      files[i].fail("the face is " + std::to_string(face.width) + " texels wide but the first is " +
                        std::to_string(first.width),
                    "six faces of the same size");
  }
}

}  // namespace

Environment parseEnvironment(const Field& field, const std::filesystem::path& folder) {
  if (!field.json().is_object()) field.wrongType("an object with a \"type\"");
  Environment environment;
  Field type = field.required("type", "one of none, sky, equirect, cube");
  environment.kind = type.choose("environment type", kEnvironmentKindNames);
  switch (environment.kind) {
    case EnvironmentKind::None:
      field.expectObject({"type"});
      return environment;
    case EnvironmentKind::Sky:
      field.expectObject({"type", "zenith", "horizon", "ground", "sun_direction", "sun_size",
                          "sun_intensity", "intensity", "resolution"});
      environment.sky = parseSky(field);
      environment.source = "procedural sky";
      break;
    case EnvironmentKind::Panorama: {
      field.expectObject({"type", "file", "intensity", "rotation", "resolution"});
      Field file = field.required("file", kImageFile);
      environment.panorama = readImage(file, folder);
      environment.source = file.string();
      if (auto f = field.optional("rotation")) environment.rotationDegrees = f->number();
      break;
    }
    case EnvironmentKind::CubeFaces:
      field.expectObject({"type", "faces", "intensity"});
      parseFaces(field.required("faces", "6 image files"), folder, environment);
      environment.source = "cube faces";
      break;
  }
  if (auto f = field.optional("intensity")) {
    environment.intensity = f->nonNegative();
    if (environment.intensity > kMaxEnvironmentIntensity)
      f->fail(formatNumber(environment.intensity) + " is too large",
              "a number from 0 to " + formatNumber(kMaxEnvironmentIntensity) +
                  " (radiance that large overflows the half-float target)");
  }
  if (auto f = field.optional("resolution")) environment.resolution = parseResolution(*f);
  return environment;
}

}  // namespace shadelab::scene_json
