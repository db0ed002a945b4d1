#include "core/vulkan/depth.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/scene/scene.h"

namespace shadelab {
namespace {

// Indexed by DepthMode, in kDepthModeNames' order.
struct DepthModeInfo {
  std::string_view formatName;
  VkFormat format;
};
constexpr DepthModeInfo kInfo[] = {
    {"D16_UNORM", VK_FORMAT_D16_UNORM},
    {"X8_D24_UNORM_PACK32", VK_FORMAT_X8_D24_UNORM_PACK32},
    {"D32_SFLOAT", VK_FORMAT_D32_SFLOAT},
    {"D32_SFLOAT", VK_FORMAT_D32_SFLOAT},
};
static_assert(std::size(kInfo) == kDepthModeNames.size());

// The depth value the projection gives a point `distance` along the line of
// sight (eye space z = -distance), from the matrix the frames use.
double projectedDepth(const glm::mat4& projection, double distance) {
  double z = -distance;
  double clipZ = double(projection[2][2]) * z + double(projection[3][2]);
  double clipW = double(projection[2][3]) * z + double(projection[3][3]);
  return clipZ / clipW;
}

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

double depthResolution(const Camera& camera, DepthMode mode, double distance) {
  glm::mat4 projection = camera.projectionMatrix(1.0f, isReversedZ(mode));
  double depth = projectedDepth(projection, distance);
  double step = 0.0;
  bool clearValue = false;
  if (mode == DepthMode::D16 || mode == DepthMode::D24) {
    double levels = mode == DepthMode::D16 ? 65535.0 : 16777215.0;
    step = 1.0 / levels;
    clearValue = std::nearbyint(depth * levels) >= levels;
  } else {
    float stored = float(depth);
    step = double(std::nextafter(stored, std::numeric_limits<float>::infinity())) - double(stored);
    clearValue = !isReversedZ(mode) && stored >= 1.0f;
  }
  if (clearValue) return std::numeric_limits<double>::infinity();
  double h = distance * 1e-6;
  double rate = std::abs(projectedDepth(projection, distance + h) -
                         projectedDepth(projection, distance - h)) /
                (2.0 * h);
  return rate > 0.0 ? step / rate : std::numeric_limits<double>::infinity();
}

std::optional<std::string> depthPrecisionWarning(const Camera& camera, DepthMode mode,
                                                 double farthest) {
  double target = glm::length(glm::dvec3(camera.at) - glm::dvec3(camera.eye));
  // What lies past the far plane is clipped, and depth is 1 on it: the
  // farthest point looked at is just inside.
  const double inside = double(camera.far) * (1.0 - 1e-3);
  for (auto [distance, what] :
       {std::pair{target, "the camera's target"},
        std::pair{std::min(farthest, inside), "the scene's farthest point"}}) {
    if (!(distance > camera.near && distance < camera.far)) continue;
    double resolution = depthResolution(camera, mode, distance);
    if (!(resolution > 0.01 * distance)) continue;  // a NaN says nothing either
    std::string where = std::string(what) + ", " + shortNumber(distance) + " away";
    std::string setting = "depth mode " + std::string(depthModeName(mode)) + " with near " +
                          shortNumber(camera.near) + " and far " + shortNumber(camera.far);
    // Perspective depth crowds near the near plane, orthographic depth is
    // spread evenly; reversed-Z already spends float's precision well.
    std::string fix = camera.projection == Projection::Orthographic || isReversedZ(mode)
                          ? "bring the camera's far plane nearer"
                          : "raise the camera's near plane or use the reversed depth mode";
    if (std::isinf(resolution))
      return setting + ": at " + where +
             ", depth rounds to the far plane's and surfaces are not drawn; " + fix;
    return setting + ": at " + where + ", depths less than " + shortNumber(resolution) + " (" +
           shortNumber(100.0 * resolution / distance) +
           "% of the distance) apart are not told apart, so surfaces that close z-fight; " + fix;
  }
  return std::nullopt;
}

VkFormat depthFormat(DepthMode mode) {
  return kInfo[int(mode)].format;
}
bool isReversedZ(DepthMode mode) {
  return mode == DepthMode::ReversedZ;
}
float depthClearValue(DepthMode mode) {
  return isReversedZ(mode) ? 0.0f : 1.0f;
}
VkCompareOp depthCompareOp(DepthMode mode) {
  return isReversedZ(mode) ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS;
}
std::string_view depthFormatName(DepthMode mode) {
  return kInfo[int(mode)].formatName;
}

}  // namespace shadelab
