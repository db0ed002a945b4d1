#pragma once
// A scene's environment: what surrounds it at infinity, seen behind the
// objects (the skybox) and in their reflections and refractions. None (the
// background colour), a procedural sky, an equirectangular panorama, or six
// cube faces. On the device every kind becomes one RGBA16F cube map
// (src/passes/environment_builder.h).
//
// Conventions, shared with the shaders (shaders/cube.glsl, shaders/sky.glsl):
// - World space is right-handed, y up. The cube is looked up with world
//   directions, face = array layer 0..5 = +X, -X, +Y, -Y, +Z, -Z, each face's
//   (s, t) as in Vulkan's cube map face selection table, row 0 = t 0.
// - A panorama's u runs with longitude: its centre column looks along -Z (the
//   default camera's view), u = 0.75 along +X, u = 0 and 1 along +Z; row 0
//   (v = 0) is straight up, the bottom row straight down.
#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <string>

#include "core/base/image.h"
#include "core/base/names.h"
#include "interface.h"

namespace shadelab {

enum class EnvironmentKind { None, Sky, Panorama, CubeFaces };
inline constexpr NameTable<EnvironmentKind, 4> kEnvironmentKindNames = {
    {{EnvironmentKind::None, "none"},
     {EnvironmentKind::Sky, "sky"},
     {EnvironmentKind::Panorama, "equirect"},
     {EnvironmentKind::CubeFaces, "cube"}}};

// Sky = a gradient zenith -> horizon -> ground, sqrt-shaped in the elevation,
// plus a sun disc with a soft edge (its outer half).
struct SkyDesc {
  glm::vec3 zenith{0.12f, 0.3f, 0.75f};
  glm::vec3 horizon{0.75f, 0.82f, 0.95f};
  glm::vec3 ground{0.22f, 0.2f, 0.18f};
  // The way sunlight travels, like a directional light's direction.
  glm::vec3 sunDirection{-0.4f, -0.6f, -0.7f};
  float sunSizeDegrees = 3.0f;    // angular diameter; 0: no sun
  glm::vec3 sunIntensity{20.0f};  // radiance of the disc (HDR)
  bool operator==(const SkyDesc& other) const;
};

struct Environment {
  EnvironmentKind kind = EnvironmentKind::None;
  SkyDesc sky;
  std::shared_ptr<const ImageRgba> panorama;  // linear, 2:1 is typical (any size)
  // Linear, square, all the same size, in layer order +X, -X, +Y, -Y, +Z, -Z.
  std::array<std::shared_ptr<const ImageRgba>, 6> faces;
  float intensity = 1.0f;        // multiplies every kind
  float rotationDegrees = 0.0f;  // panorama: turned about +y (counter-clockwise from above)
  uint32_t resolution = 0;       // cube face size in texels; 0: chosen by cubeResolution()
  std::string source;            // the file(s) or generator it came from, for messages

  bool present() const { return kind != EnvironmentKind::None; }
  // Images compare by identity: copies of a scene share them.
  bool operator==(const Environment&) const = default;
};

// The face size the cube map gets: the faces' own size; else `resolution`
// if set; else a panorama's width / 4 rounded up to a power of two (one cube texel
// per panorama texel at a face centre) in 64..2048, or 512 for the sky
// (its sun's edge is HDR: sharper than a bilinear 256 face shows smoothly).
uint32_t cubeResolution(const Environment& environment);

// Vulkan's cube face table (sc, tc, ma per major axis), inverted: the
// (unnormalised) direction through (s, t) in 0..1 on `face`.
glm::vec3 cubeFaceDirection(uint32_t face, glm::vec2 st);
struct CubeCoordinate {
  uint32_t face = 0;
  glm::vec2 st{0.5f};
};
// The face selection itself: the major axis picks the face (ties as Vulkan's
// table order does not matter for continuous content), then s and t.
CubeCoordinate cubeCoordinate(glm::vec3 direction);

// Equirectangular mapping (see the conventions above). Directions need not be unit.
glm::vec2 equirectCoordinates(glm::vec3 direction);
glm::vec3 equirectDirection(glm::vec2 uv);

// The sky as the device evaluates it (shaders/sky.glsl): parameters with the
// intensity folded in, and the radiance along a unit direction.
gpu::SkyParameters skyParameters(const SkyDesc& sky, float intensity, uint32_t faceSize);
glm::vec3 skyRadiance(const gpu::SkyParameters& sky, glm::vec3 direction);

// The environment's radiance along a direction on the CPU (bilinear in the
// panorama or face; what the device's cube approximates). None gives black.
glm::vec3 environmentRadiance(const Environment& environment, glm::vec3 direction);

// Reads an image file as linear RGBA (ImageReader: libpng or OpenImageIO): 8- and 16-bit files
// (JPEG, PNG) are sRGB-decoded, float files (HDR, EXR) are taken as linear.
// Throws InputError naming the file.
ImageRgba readLinearImage(const std::filesystem::path& path);

}  // namespace shadelab
