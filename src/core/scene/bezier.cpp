#include "core/scene/bezier.h"

#include <algorithm>
#include <cmath>

namespace shadelab {

namespace {

// Builds a matrix from its rows, so the code reads like the textbook; GLM's
// constructor takes columns.
glm::mat4 fromRows(const glm::vec4& r0, const glm::vec4& r1, const glm::vec4& r2,
                   const glm::vec4& r3) {
  return glm::transpose(glm::mat4(r0, r1, r2, r3));
}

glm::dvec4 bernstein(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

glm::dvec4 bernsteinDerivative(double t) {
  const double s = 1.0 - t;
  return {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t};
}

// Patch evaluation runs in double: at a collapsed edge dP/dv is a sum of equal
// points times weights summing to zero, and float rounding would leave a
// random-direction residue large enough to fool the degeneracy test.
struct PatchDerivatives {
  glm::dvec3 p{0.0};
  glm::dvec3 pu{0.0};
  glm::dvec3 pv{0.0};
};

PatchDerivatives evalDerivatives(const BezierPatch& patch, double u, double v) {
  const glm::dvec4 bu = bernstein(u);
  const glm::dvec4 dbu = bernsteinDerivative(u);
  const glm::dvec4 bv = bernstein(v);
  const glm::dvec4 dbv = bernsteinDerivative(v);
  PatchDerivatives d;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const glm::dvec3 c(patch.control[4 * i + j]);
      d.p += bu[i] * bv[j] * c;
      d.pu += dbu[i] * bv[j] * c;
      d.pv += bu[i] * dbv[j] * c;
    }
  }
  return d;
}

double squaredExtent(const BezierPatch& patch) {
  glm::dvec3 lo(patch.control[0]);
  glm::dvec3 hi = lo;
  for (const glm::vec3& c : patch.control) {
    lo = glm::min(lo, glm::dvec3(c));
    hi = glm::max(hi, glm::dvec3(c));
  }
  const double extent = glm::length(hi - lo);
  return extent * extent;
}

// The derivatives that define the normal and tangent frame at (u, v). Where
// cross(Pu, Pv) vanishes (a whole edge collapsed to a point, as at the teapot's
// lid knob and bottom centre) the frame is taken a little way into the patch,
// which approaches the limit normal as the nudge shrinks.
PatchDerivatives frameDerivatives(const BezierPatch& patch, double u, double v,
                                  const PatchDerivatives& exact) {
  const double threshold = 1e-12 * squaredExtent(patch);
  if (glm::length(glm::cross(exact.pu, exact.pv)) > threshold) {
    return exact;
  }
  for (double nudge : {1e-4, 1e-3, 1e-2, 1e-1}) {
    const double nu = u + (0.5 - u) * 2.0 * nudge;
    const double nv = v + (0.5 - v) * 2.0 * nudge;
    const PatchDerivatives d = evalDerivatives(patch, nu, nv);
    if (glm::length(glm::cross(d.pu, d.pv)) > threshold) {
      return d;
    }
  }
  return exact;
}

glm::dvec3 frameNormal(const PatchDerivatives& frame) {
  const glm::dvec3 n = glm::cross(frame.pu, frame.pv);
  const double len = glm::length(n);
  // Only a patch collapsed to a curve or point gets here; it has no surface to face.
  return len > 0.0 ? n / len : glm::dvec3(0.0, 1.0, 0.0);
}

// dP/du is perpendicular to cross(dP/du, dP/dv), so it needs no Gram-Schmidt step; only a
// patch collapsed to a point has no dP/du and gets an arbitrary perpendicular.
glm::vec4 frameTangent(const PatchDerivatives& frame, const glm::dvec3& n) {
  glm::dvec3 t = frame.pu;
  if (glm::length(t) <= 0.0) {
    t = std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1.0, 0.0, 0.0))
                            : glm::cross(n, glm::dvec3(0.0, 1.0, 0.0));
  }
  t = glm::normalize(t);
  // Bitangent convention B = w * cross(N, T), as in MikkTSpace.
  const double w = glm::dot(glm::cross(n, t), frame.pv) < 0.0 ? -1.0 : 1.0;
  return {glm::vec3(t), static_cast<float>(w)};
}

}  // namespace

glm::vec4 powerBasis(float u) {
  return {u * u * u, u * u, u, 1.0f};
}

glm::mat4 bezierBasisMatrix() {
  return fromRows({-1.0f, 3.0f, -3.0f, 1.0f}, {3.0f, -6.0f, 3.0f, 0.0f}, {-3.0f, 3.0f, 0.0f, 0.0f},
                  {1.0f, 0.0f, 0.0f, 0.0f});
}

glm::mat4 interpolatingBasisMatrix() {
  // Inverse of the sampling matrix S whose rows are powerBasis(0), (1/3), (2/3), (1),
  // worked out by hand: S M_I = I makes u^T M_I G pass through G's rows at those u.
  return fromRows({-4.5f, 13.5f, -13.5f, 4.5f}, {9.0f, -22.5f, 18.0f, -4.5f},
                  {-5.5f, 9.0f, -4.5f, 1.0f}, {1.0f, 0.0f, 0.0f, 0.0f});
}

glm::vec4 bezierBlending(float u) {
  return glm::vec4(bernstein(u));
}

glm::vec4 bezierBlendingDerivative(float u) {
  return glm::vec4(bernsteinDerivative(u));
}

glm::vec3 evalCubic(const glm::mat4& basis, const std::array<glm::vec3, 4>& geometry, float u) {
  const glm::vec4 b = powerBasis(u) * basis;
  return b.x * geometry[0] + b.y * geometry[1] + b.z * geometry[2] + b.w * geometry[3];
}

glm::vec3 evalBezierCurve(const std::array<glm::vec3, 4>& p, float u) {
  const glm::vec4 b = bezierBlending(u);
  return b.x * p[0] + b.y * p[1] + b.z * p[2] + b.w * p[3];
}

glm::vec3 evalBezierCurveDerivative(const std::array<glm::vec3, 4>& p, float u) {
  const glm::vec4 b = bezierBlendingDerivative(u);
  return b.x * p[0] + b.y * p[1] + b.z * p[2] + b.w * p[3];
}

PatchSample evalBezierPatch(const BezierPatch& patch, float u, float v) {
  const PatchDerivatives exact = evalDerivatives(patch, u, v);
  const PatchDerivatives frame = frameDerivatives(patch, u, v, exact);
  return {glm::vec3(exact.p), glm::vec3(exact.pu), glm::vec3(exact.pv),
          glm::vec3(frameNormal(frame))};
}

Mesh tessellatePatches(const std::vector<BezierPatch>& patches, uint32_t level) {
  level = std::max(level, 1u);
  const uint32_t side = level + 1;
  Mesh mesh;
  mesh.vertices.reserve(patches.size() * side * side);
  mesh.indices.reserve(patches.size() * level * level * 6);

  for (const BezierPatch& patch : patches) {
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    for (uint32_t i = 0; i <= level; ++i) {
      for (uint32_t j = 0; j <= level; ++j) {
        const double u = static_cast<double>(i) / level;
        const double v = static_cast<double>(j) / level;
        const PatchDerivatives exact = evalDerivatives(patch, u, v);
        const PatchDerivatives frame = frameDerivatives(patch, u, v, exact);
        const glm::dvec3 n = frameNormal(frame);
        Vertex vertex{};
        vertex.position = glm::vec3(exact.p);
        vertex.normal = glm::vec3(n);
        vertex.uv = glm::vec2(static_cast<float>(u), static_cast<float>(v));
        vertex.tangent = frameTangent(frame, n);
        mesh.vertices.push_back(vertex);
      }
    }
    // Quad (i, j)-(i+1, j+1) as two triangles; the order 00, 10, 11 turns from
    // dP/du towards dP/dv, so it is counter-clockwise seen from where the normal points.
    for (uint32_t i = 0; i < level; ++i) {
      for (uint32_t j = 0; j < level; ++j) {
        const uint32_t p00 = base + i * side + j;
        const uint32_t p10 = p00 + side;
        const uint32_t p11 = p10 + 1;
        const uint32_t p01 = p00 + 1;
        mesh.indices.insert(mesh.indices.end(), {p00, p10, p11, p00, p11, p01});
      }
    }
  }
  return mesh;
}

}  // namespace shadelab
