#include "core/scene/billboard_outline.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/scene/texture.h"

namespace shadelab {
namespace {

struct AlphaLevel {
  int width = 0;
  int height = 0;
  std::vector<float> alpha;  // row 0 at the top, as the texture
  float at(int x, int y) const { return alpha[size_t(y) * size_t(width) + size_t(x)]; }
};

int wrapIndex(int i, int n, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::ClampToEdge:
      return std::clamp(i, 0, n - 1);
    case TextureWrap::Repeat:
      return ((i % n) + n) % n;
    case TextureWrap::MirroredRepeat: {
      int m = ((i % (2 * n)) + 2 * n) % (2 * n);
      return m < n ? m : 2 * n - 1 - m;
    }
  }
  return 0;
}

// The bilinear blend at texel coordinates (x, y) (texel centres at integers).
float bilinear(const AlphaLevel& level, double x, double y, TextureWrap wrapX, TextureWrap wrapY) {
  double fx = std::floor(x), fy = std::floor(y);
  int x0 = int(fx), y0 = int(fy);
  float tx = float(x - fx), ty = float(y - fy);
  int xa = wrapIndex(x0, level.width, wrapX), xb = wrapIndex(x0 + 1, level.width, wrapX);
  int ya = wrapIndex(y0, level.height, wrapY), yb = wrapIndex(y0 + 1, level.height, wrapY);
  float top = level.at(xa, ya) + (level.at(xb, ya) - level.at(xa, ya)) * tx;
  float bottom = level.at(xa, yb) + (level.at(xb, yb) - level.at(xa, yb)) * tx;
  return top + (bottom - top) * ty;
}

// MipGeneration's chain: each level a linear-filter blit (edge-clamped) of
// the one above, sampled at the smaller level's texel centres.
std::vector<AlphaLevel> alphaLevels(const Texture& texture) {
  std::vector<AlphaLevel> levels(1);
  levels[0].width = int(texture.width);
  levels[0].height = int(texture.height);
  levels[0].alpha.resize(size_t(texture.width) * texture.height);
  for (size_t i = 0; i < levels[0].alpha.size(); ++i)
    levels[0].alpha[i] = float(texture.rgba8[i * 4 + 3]) / 255.0f;
  uint32_t count = mipLevelCount(texture.width, texture.height);
  for (uint32_t l = 1; l < count; ++l) {
    const AlphaLevel& above = levels.back();
    glm::uvec2 size = mipLevelSize(texture.width, texture.height, l);
    AlphaLevel level{int(size.x), int(size.y), {}};
    level.alpha.resize(size_t(size.x) * size.y);
    for (int y = 0; y < level.height; ++y)
      for (int x = 0; x < level.width; ++x)
        level.alpha[size_t(y) * size_t(level.width) + size_t(x)] =
            bilinear(above, (x + 0.5) * above.width / level.width - 0.5,
                     (y + 0.5) * above.height / level.height - 0.5, TextureWrap::ClampToEdge,
                     TextureWrap::ClampToEdge);
    levels.push_back(std::move(level));
  }
  return levels;
}

double cross(glm::dvec2 a, glm::dvec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Andrew's monotone chain: counter-clockwise, no collinear points.
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points) {
  std::sort(points.begin(), points.end(),
            [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<glm::vec2> hull(2 * points.size());
  size_t k = 0;
  auto turn = [](glm::vec2 o, glm::vec2 a, glm::vec2 b) {
    return cross(glm::dvec2(a - o), glm::dvec2(b - o));
  };
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

std::optional<std::vector<std::vector<glm::vec2>>> billboardAlphaHulls(const Texture& texture,
                                                                       const SamplerDesc& sampler,
                                                                       float cutoff) {
  if (texture.width == 0 || texture.height == 0 || texture.width > kMaxOutlineTextureSide ||
      texture.height > kMaxOutlineTextureSide ||
      texture.rgba8.size() != size_t(texture.width) * texture.height * 4)
    return std::nullopt;
  std::vector<AlphaLevel> levels = alphaLevels(texture);
  // Each stored level rounds to 8 bits (half a step) and llvmpipe filters in
  // fixed point: the threshold gives a step per level and two more.
  float threshold = cutoff - float(levels.size() + 2) / 255.0f;
  auto passes = [&](float alpha) { return threshold > 0.0f ? alpha >= threshold : alpha > 0.0f; };
  std::vector<glm::vec2> points;  // levels 0..l so far
  // A point's quad coordinates from st: x = s, y = 1 - t.
  auto add = [&](double s, double t) { points.emplace_back(float(s), float(1.0 - t)); };
  std::vector<std::vector<glm::vec2>> hulls;
  for (const AlphaLevel& level : levels) {
    // Nearest (the base level only: SceneTextures' nearest sampler keeps to
    // it): a passing texel's square.
    for (int y = 0; level.width == int(texture.width) && y < level.height; ++y) {
      int first = -1, last = -1;
      for (int x = 0; x < level.width; ++x)
        if (passes(level.at(x, y))) {
          if (first < 0) first = x;
          last = x;
        }
      if (first < 0) continue;
      double t0 = double(y) / level.height, t1 = double(y + 1) / level.height;
      add(double(first) / level.width, t0);
      add(double(first) / level.width, t1);
      add(double(last + 1) / level.width, t0);
      add(double(last + 1) / level.width, t1);
    }
    // Bilinear: sub-cells of half a base texel (at least half a texel of the
    // level), their corners on every texel centre and edge of the level, so
    // each lies within one bilinear piece.
    int perX = 2 * std::max(1, int(texture.width) / level.width);
    int perY = 2 * std::max(1, int(texture.height) / level.height);
    int columns = perX * level.width, rows = perY * level.height;
    std::vector<uint8_t> corner(size_t(columns + 1) * size_t(rows + 1));
    for (int j = 0; j <= rows; ++j)
      for (int i = 0; i <= columns; ++i)
        corner[size_t(j) * size_t(columns + 1) + size_t(i)] = passes(bilinear(
            level, double(i) / perX - 0.5, double(j) / perY - 0.5, sampler.wrapU, sampler.wrapV));
    auto at = [&](int i, int j) {
      return corner[size_t(j) * size_t(columns + 1) + size_t(i)] != 0;
    };
    for (int j = 0; j < rows; ++j) {
      int first = -1, last = -1;
      for (int i = 0; i < columns; ++i)
        if (at(i, j) || at(i + 1, j) || at(i, j + 1) || at(i + 1, j + 1)) {
          if (first < 0) first = i;
          last = i;
        }
      if (first < 0) continue;
      double t0 = double(j) / rows, t1 = double(j + 1) / rows;
      add(double(first) / columns, t0);
      add(double(first) / columns, t1);
      add(double(last + 1) / columns, t0);
      add(double(last + 1) / columns, t1);
    }
    points = convexHull(std::move(points));
    hulls.push_back(points);
  }
  return hulls;
}

std::optional<BillboardOutline> enclosingTriangle(const std::vector<glm::vec2>& hull,
                                                  float margin) {
  if (hull.size() < 3) return std::nullopt;
  std::vector<glm::dvec2> normals;
  for (int k = 0; k < kOutlineDirections; ++k) {
    double angle = 2.0 * std::numbers::pi * k / kOutlineDirections;
    normals.emplace_back(std::cos(angle), std::sin(angle));
  }
  for (size_t i = 0; i < hull.size(); ++i) {
    glm::dvec2 edge = glm::dvec2(hull[(i + 1) % hull.size()]) - glm::dvec2(hull[i]);
    normals.push_back(glm::normalize(glm::dvec2(edge.y, -edge.x)));  // outward (counter-clockwise)
  }
  // Each line n.p = offset touches the hull from outside, `margin` further.
  std::vector<double> offsets;
  for (glm::dvec2 n : normals) {
    double support = -std::numeric_limits<double>::infinity();
    for (glm::vec2 p : hull) support = std::max(support, glm::dot(n, glm::dvec2(p)));
    offsets.push_back(support + margin);
  }
  auto meet = [&](size_t a, size_t b) {
    double det = cross(normals[a], normals[b]);
    return glm::dvec2((offsets[a] * normals[b].y - offsets[b] * normals[a].y) / det,
                      (normals[a].x * offsets[b] - normals[b].x * offsets[a]) / det);
  };
  double best = std::numeric_limits<double>::infinity();
  std::array<glm::dvec2, 3> corners{};
  size_t n = normals.size();
  for (size_t a = 0; a < n; ++a)
    for (size_t b = a + 1; b < n; ++b) {
      double ab = cross(normals[a], normals[b]);
      if (std::abs(ab) < 1e-9) continue;
      for (size_t c = b + 1; c < n; ++c) {
        // Bounded only when the three normals surround the origin: the
        // turns a->b, b->c, c->a all the same way.
        double bc = cross(normals[b], normals[c]), ca = cross(normals[c], normals[a]);
        if (!((ab > 1e-9 && bc > 1e-9 && ca > 1e-9) || (ab < -1e-9 && bc < -1e-9 && ca < -1e-9)))
          continue;
        glm::dvec2 p = meet(a, b), q = meet(b, c), r = meet(c, a);
        double area = 0.5 * std::abs(cross(q - p, r - p));
        if (area < best) {
          best = area;
          corners = {p, q, r};
        }
      }
    }
  if (!std::isfinite(best)) return std::nullopt;
  if (cross(corners[1] - corners[0], corners[2] - corners[0]) < 0.0)
    std::swap(corners[1], corners[2]);
  BillboardOutline outline;
  for (int i = 0; i < 3; ++i) outline.corners[size_t(i)] = glm::vec2(corners[size_t(i)]);
  outline.area = float(best);
  return outline;
}

std::vector<std::optional<BillboardOutline>> billboardOutlines(const Texture& texture,
                                                               const SamplerDesc& sampler,
                                                               float cutoff) {
  std::vector<std::optional<BillboardOutline>> outlines;
  auto hulls = billboardAlphaHulls(texture, sampler, cutoff);
  if (!hulls) return outlines;
  for (const std::vector<glm::vec2>& hull : *hulls) {
    std::optional<BillboardOutline> outline = enclosingTriangle(hull, kOutlineMargin);
    if (outline && !(outline->area < 1.0f)) outline.reset();
    outlines.push_back(outline);
  }
  return outlines;
}

uint32_t billboardLevelBound(const BillboardView& view, uint32_t levels) {
  assert(levels > 0);
  uint32_t coarsest = levels - 1;
  double depth = -double(view.centre.z);
  double radius = 0.5 * glm::length(glm::dvec2(view.size));
  if (!(depth > 2.0 * radius) || !(view.focalPixels > 0.0f) || !(view.size.x > 0.0f) ||
      !(view.size.y > 0.0f))
    return coarsest;
  // Pixels per eye unit at the centre: d(pixel)/dP = f / q [[1, 0, x / q], [0, 1, y / q]].
  glm::dvec3 c(view.centre);
  double f = view.focalPixels;
  auto project = [&](glm::dvec3 d) {
    return glm::dvec2(d.x + c.x * d.z / depth, d.y + c.y * d.z / depth) * (f / depth);
  };
  // Columns: pixels per quad coordinate along x and along y.
  glm::dmat2 jacobian(project(glm::dvec3(view.right) * double(view.size.x)),
                      project(glm::dvec3(view.up) * double(view.size.y)));
  double determinant = glm::determinant(jacobian);
  if (!(std::abs(determinant) > 1e-12)) return coarsest;
  // Texels per pixel: column k = (du, dv) for a step along pixel axis k.
  glm::dmat2 texelsPerPixel =
      glm::dmat2(double(view.texels.x), 0.0, 0.0, double(view.texels.y)) * glm::inverse(jacobian);
  double rho = std::max(std::abs(texelsPerPixel[0][0]) + std::abs(texelsPerPixel[0][1]),
                        std::abs(texelsPerPixel[1][0]) + std::abs(texelsPerPixel[1][1]));
  double growth = (depth + radius) / (depth - radius);
  double lambda = std::log2(rho * growth * growth);
  if (!(lambda < double(coarsest) - 1.0)) return coarsest;
  return lambda < 0.0 ? 0u : uint32_t(std::floor(lambda)) + 1u;
}

}  // namespace shadelab
