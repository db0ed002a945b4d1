#pragma once
// The camera on the command line, for every command that draws a scene
// (render, trace, compare, view): --eye, --at, --up, --fovy and --ortho
// override what the scene file says, checked like the scene format checks a
// camera (findCameraProblem) and reported naming the option.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "core/scene/scene.h"

namespace shadelab {

struct CameraOptions {
  std::string eye, at, up;  // "X,Y,Z"; empty: the scene's
  std::optional<float> fovy;
  bool ortho = false;
};

void addCameraOptions(CLI::App* command, CameraOptions& options);

// Applies the options given to `camera` (for an image of width / height =
// `aspect`). --ortho frames what the perspective camera frames at the
// distance of --at: a view volume of height 2 |at - eye| tan(fovy / 2).
// Throws InputError naming the option, its value and what was expected.
void applyCameraOptions(const CameraOptions& options, float aspect, Camera& camera);

}  // namespace shadelab
