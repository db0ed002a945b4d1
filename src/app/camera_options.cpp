#include "app/camera_options.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/base/errors.h"

namespace shadelab {
namespace {

// "X,Y,Z" of finite numbers; throws InputError naming the option.
glm::vec3 parseTriple(const std::string& text, const std::string& option) {
  glm::vec3 v;
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 3; ++i) {
    auto [next, error] = std::from_chars(p, end, v[i]);
    bool separatorOk = i < 2 ? (next != end && *next == ',') : next == end;
    if (error != std::errc() || !separatorOk || !std::isfinite(v[i]))
      throw InputError(option + " '" + text + "': expected three finite numbers X,Y,Z");
    p = next + 1;
  }
  return v;
}

std::string formatDegrees(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string optionFor(const std::string& field) {
  if (field == "eye" || field == "at" || field == "up" || field == "fovy") return "--" + field;
  return "--ortho";  // near/far and the sides: only --ortho sets them from the command line
}

}  // namespace

void addCameraOptions(CLI::App* command, CameraOptions& options) {
  command->add_option("--eye", options.eye, "Camera position X,Y,Z (default: the scene's)");
  command->add_option("--at", options.at, "Point the camera looks at X,Y,Z (default: the scene's)");
  command->add_option("--up", options.up, "Camera up vector X,Y,Z (default: the scene's)");
  command->add_option("--fovy", options.fovy,
                      "Vertical field of view in degrees, 0 < DEG < 180 (perspective)");
  command->add_flag("--ortho", options.ortho,
                    "Orthographic projection framing what the perspective camera frames at the "
                    "distance of --at");
}

void applyCameraOptions(const CameraOptions& options, float aspect, Camera& camera) {
  if (!options.eye.empty()) camera.eye = parseTriple(options.eye, "--eye");
  if (!options.at.empty()) camera.at = parseTriple(options.at, "--at");
  if (!options.up.empty()) camera.up = parseTriple(options.up, "--up");
  if (options.fovy) {
    float fovy = *options.fovy;
    if (!(fovy > 0.0f && fovy < 180.0f))
      throw InputError("--fovy " + formatDegrees(fovy) +
                       ": expected degrees greater than 0 and less than 180");
    if (camera.projection != Projection::Perspective)
      throw InputError(
          "--fovy: the scene's camera is not a perspective camera (use --ortho to "
          "set an orthographic view, or drop --fovy)");
    camera.fovyDegrees = fovy;
  }
  if (std::optional<CameraProblem> problem = findCameraProblem(camera))
    throw InputError(optionFor(problem->field) + ": " + problem->problem + ", expected " +
                     problem->expected);
  if (options.ortho) {
    if (camera.projection == Projection::Frustum)
      throw InputError(
          "--ortho: the scene's camera is an off-axis frustum; expected a "
          "perspective or orthographic camera to convert");
    if (camera.projection == Projection::Perspective) {
      float halfHeight =
          glm::length(camera.at - camera.eye) * std::tan(glm::radians(camera.fovyDegrees) / 2.0f);
      camera.bottom = -halfHeight;
      camera.top = halfHeight;
      camera.left = -halfHeight * aspect;
      camera.right = halfHeight * aspect;
      camera.projection = Projection::Orthographic;
    }
  }
}

}  // namespace shadelab
