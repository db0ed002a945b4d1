#include "measure/billboard_failures.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/scene/transform.h"

namespace shadelab {
namespace {

constexpr float kOrthoUnitsHigh = 6.0f;  // the orthographic view's height: 30 px a unit at 180 rows
constexpr float kCutDistance = 6.0f;     // the eye's distance in the ground-cut views

bool isWhite(glm::u8vec4 pixel) {
  return pixel.r > 200 && pixel.g > 200 && pixel.b > 200;
}

uint64_t whitePixels(const ImageU8& image) {
  uint64_t count = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) count += isWhite(image.at(x, y));
  return count;
}

// One opaque white billboard, unlit, anchored at its centre.
Scene quadScene(BillboardKind kind, glm::vec2 size, glm::vec3 anchor) {
  Scene scene;
  scene.name = "billboard-failures";
  scene.background = glm::vec3(0.0f);
  scene.textures.push_back({"white", 4, 4, std::vector<uint8_t>(4 * 4 * 4, 255), true});
  Billboard quad;
  quad.name = "quad";
  quad.kind = kind;
  quad.anchor = BillboardAnchor::Center;
  quad.size = size;
  quad.material.kd = glm::vec3(1.0f);
  quad.material.diffuseMap.texture = 0;
  quad.instances = {translation(anchor)};
  scene.billboards.push_back(quad);
  return scene;
}

// An eye `distance` from `target`, `elevation` degrees above the horizontal,
// looking at it with the image's up in the vertical plane through both (so
// looking straight down is no special case).
Camera elevatedCamera(glm::vec3 target, float distance, float elevationDegrees) {
  float angle = glm::radians(elevationDegrees);
  Camera camera;
  camera.eye = target + distance * glm::vec3(0.0f, std::sin(angle), std::cos(angle));
  camera.at = target;
  camera.up = glm::vec3(0.0f, std::cos(angle), -std::sin(angle));
  camera.near = 0.1f;
  camera.far = 5.0f * distance;
  return camera;
}

ImageU8 renderUnlit(Renderer& renderer, const Scene& scene, uint32_t width, uint32_t height) {
  RenderSettings settings{width, height, ShadingModel::Unlit};
  settings.environment = false;
  return encodeSrgb8(renderer.renderToImage(scene, settings).image);
}

// The quad's right and up in world space, as billboard.vert builds them in
// eye space (the same vectors, rotated): spherical faces the eye point,
// cylindrical turns about +y only.
void quadFrame(BillboardKind kind, glm::vec3 anchor, glm::vec3 eye, glm::vec3& right,
               glm::vec3& up) {
  glm::vec3 axis(0.0f, 1.0f, 0.0f);
  glm::vec3 toEye = glm::normalize(eye - anchor);
  if (kind == BillboardKind::Spherical) {
    right = glm::normalize(glm::cross(axis, toEye));
    up = glm::cross(toEye, right);
  } else {
    up = axis;
    right = glm::normalize(glm::cross(axis, toEye));
  }
}

// A world point to pixel coordinates (x right, y down, pixel centres at +0.5).
glm::dvec2 toPixel(const Camera& camera, uint32_t width, uint32_t height, glm::vec3 point) {
  glm::mat4 clipFromWorld =
      camera.projectionMatrix(float(width) / float(height)) * camera.viewMatrix();
  glm::dvec4 clip = glm::dvec4(clipFromWorld * glm::vec4(point, 1.0f));
  return {(clip.x / clip.w * 0.5 + 0.5) * width, (clip.y / clip.w * 0.5 + 0.5) * height};
}

}  // namespace

BillboardCoverage measureBillboardCoverage(Renderer& renderer, BillboardKind kind,
                                           float elevationDegrees, uint32_t width,
                                           uint32_t height) {
  const glm::vec2 size(2.0f, 3.0f);
  Scene scene = quadScene(kind, size, glm::vec3(0.0f));
  scene.camera = elevatedCamera(glm::vec3(0.0f), 10.0f, elevationDegrees);
  Camera& camera = scene.camera;
  camera.projection = Projection::Orthographic;
  camera.top = 0.5f * kOrthoUnitsHigh;
  camera.bottom = -camera.top;
  camera.right = camera.top * float(width) / float(height);  // square pixels
  camera.left = -camera.right;
  BillboardCoverage result;
  result.image = renderUnlit(renderer, scene, width, height);
  result.covered = whitePixels(result.image);
  double pixelsPerUnit = double(height) / kOrthoUnitsHigh;
  result.fullArea = double(size.x) * size.y * pixelsPerUnit * pixelsPerUnit;
  // Orthographic: a cylindrical quad stays vertical, its normal horizontal,
  // so the view direction meets it at the elevation; a spherical one faces
  // the view direction. (A vertical quad seen from straight above has no area.)
  double slant = kind == BillboardKind::Cylindrical
                     ? std::max(0.0, std::cos(glm::radians(double(elevationDegrees))))
                     : 1.0;
  result.expected = result.fullArea * slant;
  return result;
}

BillboardGroundCut measureGroundCut(Renderer& renderer, BillboardKind kind, float elevationDegrees,
                                    float sink, uint32_t width, uint32_t height) {
  const glm::vec2 size(2.0f, 2.0f);
  // Off the view's centre, so the cut crosses the image aslant and off the
  // pixel grid (the view looks at the origin).
  glm::vec3 anchor(0.35f, -sink, 0.25f);
  Scene scene = quadScene(kind, size, anchor);
  scene.camera = elevatedCamera(glm::vec3(0.0f), kCutDistance, elevationDegrees);
  scene.camera.fovyDegrees = 45.0f;
  BillboardGroundCut result;
  result.unhidden = whitePixels(renderUnlit(renderer, scene, width, height));
  uint32_t ground = scene.addShape({.kind = ShapeKind::Plane, .size = 20.0f});
  Material green;
  green.kd = glm::vec3(0.1f, 0.5f, 0.1f);
  scene.objects.push_back({"ground", ground, glm::mat4(1.0f), green});
  result.image = renderUnlit(renderer, scene, width, height);
  result.visible = whitePixels(result.image);

  // Where the quad's plane meets y = 0: anchor.y + up.y t = 0, t along the
  // quad's height from its centre.
  glm::vec3 right, up;
  quadFrame(kind, anchor, scene.camera.eye, right, up);
  float t = sink / up.y;
  result.cutHeight = 0.5 + double(t) / size.y;
  glm::vec3 cutLeft = anchor + up * t - right * (0.5f * size.x);
  glm::vec3 cutRight = anchor + up * t + right * (0.5f * size.x);
  glm::dvec2 a = toPixel(scene.camera, width, height, cutLeft);
  glm::dvec2 b = toPixel(scene.camera, width, height, cutRight);
  glm::vec3 bottom = anchor - up * (0.5f * size.y);
  glm::dvec2 bottomLeft = toPixel(scene.camera, width, height, bottom - right * (0.5f * size.x));
  glm::dvec2 bottomRight = toPixel(scene.camera, width, height, bottom + right * (0.5f * size.x));
  auto rowAt = [](glm::dvec2 p, glm::dvec2 q, double x) {
    return p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x);
  };
  // Per column inside the cut (2 columns in from its ends): the cut is the
  // bottom of the white run, between the last white pixel centre and the next.
  std::vector<glm::dvec2> measured;
  double errorSum = 0.0, gapSum = 0.0;
  for (uint32_t x = 0; x < width; ++x) {
    double centreX = x + 0.5;
    if (centreX < std::min(a.x, b.x) + 2.0 || centreX > std::max(a.x, b.x) - 2.0) continue;
    int32_t lowest = -1;
    for (uint32_t y = 0; y < height; ++y)
      if (isWhite(result.image.at(x, y))) lowest = int32_t(y);
    if (lowest < 0) continue;
    double cut = lowest + 1.0;
    double error = std::abs(cut - rowAt(a, b, centreX));
    errorSum += error;
    result.maxRowError = std::max(result.maxRowError, error);
    gapSum += rowAt(bottomLeft, bottomRight, centreX) - cut;
    measured.push_back({centreX, cut});
  }
  result.columns = uint32_t(measured.size());
  if (!measured.empty()) {
    result.meanRowError = errorSum / double(measured.size());
    result.bottomEdgeGap = gapSum / double(measured.size());
    // Least squares row = c0 + c1 x, and the largest residual.
    double n = double(measured.size()), sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (glm::dvec2 p : measured) {
      sx += p.x, sy += p.y, sxx += p.x * p.x, sxy += p.x * p.y;
    }
    double denominator = n * sxx - sx * sx;
    double c1 = denominator != 0.0 ? (n * sxy - sx * sy) / denominator : 0.0;
    double c0 = (sy - c1 * sx) / n;
    for (glm::dvec2 p : measured)
      result.maxLineResidual = std::max(result.maxLineResidual, std::abs(p.y - (c0 + c1 * p.x)));
  }
  // The expected cut drawn over the render, one red pixel a column.
  for (uint32_t x = 0; x < width; ++x) {
    double centreX = x + 0.5;
    if (centreX < std::min(a.x, b.x) || centreX > std::max(a.x, b.x)) continue;
    double row = std::floor(rowAt(a, b, centreX));
    if (row >= 0.0 && row < double(height))
      result.image.set(x, uint32_t(row), glm::u8vec4(255, 0, 0, 255));
  }
  return result;
}

}  // namespace shadelab
