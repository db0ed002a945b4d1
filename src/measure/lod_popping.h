#pragma once
// Levels of detail popping, measured: a camera path over procedural spheres
// and teapots with detail chains, drawn with --lod auto and with --lod off.
// A level switch shows as a jump between consecutive frames that the camera's
// own motion does not explain; the lod-off frames give that motion's share.
// The levels chosen are followed on the CPU with the renderer's own inputs
// (the uploaded draws, their chains and chooseLevel), checked against the
// triangles the renderer submitted.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/base/image.h"
#include "passes/renderer.h"

namespace shadelab {

// Six shapes in a diagonal row into the distance (spheres of 128 slices,
// teapots of 16 quads per patch at half size), the chains of
// tests/test_gltf_render.cpp's procedural levels-of-detail test.
Scene lodPoppingScene();

struct LodCameraPath {
  std::string name;
  std::vector<Camera> cameras;
  std::vector<float> eyeZ;  // per camera: the eye's z, the path's parameter
};
// The eye moving back along +z from z 4 to 40 in `frames` steps of the
// same factor, always looking the same way: every shape crosses switching
// distances.
LodCameraPath dollyPath(uint32_t frames);
// The eye oscillating (amplitude 3%, 12 frames a period) about the distance
// at which the nearest sphere's 16-slice level reaches the bound
// (lodErrorPixels at `height` rows): without hysteresis it switches twice a
// period.
LodCameraPath oscillationPath(const Scene& scene, Renderer& renderer, uint32_t frames,
                              uint32_t height, float lodErrorPixels = 0.5f);

struct LodPoppingFrame {
  uint64_t triangles = 0;        // submitted with lod (the CPU model's count)
  uint32_t switches = 0;         // objects whose level differs from the previous frame's
  double stepLod = 0.0;          // mean FLIP against the previous frame, lod on (0 at frame 0)
  double stepOff = 0.0;          // the same with lod off: the camera's motion alone
  double errorAgainstOff = 0.0;  // mean FLIP against the lod-off frame of the same camera
  // Pixels where the frame's departure from its lod-off twin changed since
  // the previous frame by more than kPopCodes in a channel: what changed
  // between frames that the camera's motion does not explain.
  uint64_t poppedPixels = 0;
};
inline constexpr int kPopCodes = 8;  // of 255, sRGB
// Whether pixel `pixel` popped between two frames (lod and lod-off, each
// before and now), and an image of them: popped pixels red over the lod
// frame darkened.
bool popped(const ImageU8& lodBefore, const ImageU8& offBefore, const ImageU8& lod,
            const ImageU8& off, size_t pixel);
ImageU8 popMap(const ImageU8& lodBefore, const ImageU8& offBefore, const ImageU8& lod,
               const ImageU8& off);

struct LodPoppingRun {
  std::string path;
  float bound = 0.5f;  // lodErrorPixels
  float hysteresis = kLodHysteresis;
  std::vector<LodPoppingFrame> frames;
  // The CPU model's triangles of the last frame equal what the renderer
  // submitted (RenderStats of the sequence: its last frame's).
  bool modelAgrees = false;
  uint64_t rendererTriangles = 0;
  // The frames around the switch whose step stands out most against the
  // lod-off step (empty without a switch), with the lod-off pair.
  uint32_t shownFrame = 0;
  ImageU8 shownBefore, shownAfter, offBefore, offAfter;

  uint32_t switches() const;      // level changes, summed over objects
  uint32_t switchFrames() const;  // frames with at least one
  // Sum of stepLod over sum of stepOff, over frames 1.. with a switch
  // (atSwitch) or without: 1 where lod changes nothing between frames.
  double stepRatio(bool atSwitch) const;
  // Mean poppedPixels over frames 1.. with a switch (atSwitch) or without.
  double meanPopped(bool atSwitch) const;
  double meanErrorAgainstOff() const;
  double maxErrorAgainstOff() const;
};

// The path drawn with lod off, then with lod at each hysteresis (a run each).
std::vector<LodPoppingRun> measureLodPopping(Renderer& renderer, const Scene& scene,
                                             const LodCameraPath& path,
                                             std::span<const float> hysteresis, uint32_t width,
                                             uint32_t height, float lodErrorPixels = 0.5f);

}  // namespace shadelab
