// LDR FLIP, written from the description in Andersson, Nilsson, Akenine-Moller,
// Oskarsson, Astrom and Fairchild, "FLIP: A Difference Evaluator for
// Alternating Images", HPG 2020. Two pipelines per pixel:
//  - colour: both images in the opponent space YCxCz, each channel filtered
//    by a contrast sensitivity function (CSF) for the viewing distance, back
//    to L*a*b*, Hunt-adjusted (a*, b* scaled by 0.01 L*), compared with the
//    HyAB distance |dL| + sqrt(da^2 + db^2), raised to qc = 0.7 and mapped to
//    [0, 1] with pc = 0.4, pt = 0.95 against the green-blue distance;
//  - features: edges (first Gaussian derivative) and points (second
//    derivative) of the luminance, difference raised to qf = 0.5;
// combined as colour^(1 - features).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/metrics/image_filter.h"
#include "core/metrics/metrics.h"

namespace shadelab {
namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kQc = 0.7f, kQf = 0.5f, kPc = 0.4f, kPt = 0.95f;
constexpr float kFeatureWidthDegrees = 0.082f;

// Linear sRGB <-> CIE XYZ (D65), IEC 61966-2-1.
glm::vec3 rgbToXyz(glm::vec3 c) {
  return {0.4124564f * c.r + 0.3575761f * c.g + 0.1804375f * c.b,
          0.2126729f * c.r + 0.7151522f * c.g + 0.0721750f * c.b,
          0.0193339f * c.r + 0.1191920f * c.g + 0.9503041f * c.b};
}
glm::vec3 xyzToRgb(glm::vec3 c) {
  return {3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z,
          -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z,
          0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z};
}
// The reference white: XYZ of linear RGB (1, 1, 1).
const glm::vec3 kWhite = rgbToXyz(glm::vec3(1.0f));

// YCxCz: L*a*b* without the cube root (linear in XYZ), so filtering there
// is filtering the light.
glm::vec3 xyzToYcxcz(glm::vec3 xyz) {
  const glm::vec3 n = xyz / kWhite;
  return {116.0f * n.y - 16.0f, 500.0f * (n.x - n.y), 200.0f * (n.y - n.z)};
}
glm::vec3 ycxczToXyz(glm::vec3 c) {
  const float y = (c.x + 16.0f) / 116.0f;
  return glm::vec3(c.y / 500.0f + y, y, y - c.z / 200.0f) * kWhite;
}

float labCurve(float t) {
  constexpr float delta = 6.0f / 29.0f;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}
glm::vec3 xyzToLab(glm::vec3 xyz) {
  const glm::vec3 n = xyz / kWhite;
  const float fx = labCurve(n.x), fy = labCurve(n.y), fz = labCurve(n.z);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// Hunt effect: chroma appears weaker at low lightness.
glm::vec3 huntAdjusted(glm::vec3 lab) {
  return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z};
}
float hyab(glm::vec3 a, glm::vec3 b) {
  const glm::vec3 d = a - b;
  return std::abs(d.x) + std::sqrt(d.y * d.y + d.z * d.z);
}
glm::vec3 huntLabOfLinear(glm::vec3 rgb) {
  return huntAdjusted(xyzToLab(rgbToXyz(rgb)));
}

// One channel's CSF in the spatial domain, as a sum of Gaussians
// S(r) = sum_i a_i sqrt(pi / b_i) exp(-pi^2 r^2 / b_i), r in degrees; the
// parameters are the paper's fits for the achromatic, red-green and
// blue-yellow channels.
struct Csf {
  std::array<float, 2> a, b;
};
constexpr Csf kCsfAchromatic{{1.0f, 0.0f}, {0.0047f, 1e-5f}};
constexpr Csf kCsfRedGreen{{1.0f, 0.0f}, {0.0053f, 1e-5f}};
constexpr Csf kCsfBlueYellow{{34.1f, 13.5f}, {0.04f, 0.025f}};

// Each Gaussian term is separable; the terms are filtered one by one and
// summed with the weights that make the whole 2D kernel sum to 1.
Plane filterCsf(const Plane& channel, const Csf& csf, int radius, float pixelsPerDegree) {
  Plane result(channel.width, channel.height);
  float total = 0.0f;
  std::array<std::vector<float>, 2> terms;
  std::array<float, 2> weights{};
  for (int i = 0; i < 2; ++i) {
    if (csf.a[size_t(i)] == 0.0f) continue;
    std::vector<float>& g = terms[size_t(i)];
    float sum = 0.0f;
    for (int x = -radius; x <= radius; ++x) {
      const float r = float(x) / pixelsPerDegree;
      g.push_back(std::exp(-kPi * kPi * r * r / csf.b[size_t(i)]));
      sum += g.back();
    }
    weights[size_t(i)] = csf.a[size_t(i)] * std::sqrt(kPi / csf.b[size_t(i)]);
    total += weights[size_t(i)] * sum * sum;
  }
  for (int i = 0; i < 2; ++i) {
    if (terms[size_t(i)].empty()) continue;
    const Plane filtered = convolveSeparable(channel, terms[size_t(i)], terms[size_t(i)]);
    const float weight = weights[size_t(i)] / total;
    for (size_t p = 0; p < result.values.size(); ++p)
      result.values[p] += weight * filtered.values[p];
  }
  return result;
}

// The CSF-filtered image, back in linear RGB clamped to [0, 1], as Hunt-adjusted L*a*b*.
std::vector<glm::vec3> filteredLab(const ImageU8& image, float pixelsPerDegree) {
  const size_t count = size_t(image.width) * image.height;
  std::array<Plane, 3> opponent;
  for (Plane& plane : opponent) plane = Plane(image.width, image.height);
  for (size_t p = 0; p < count; ++p) {
    glm::vec3 rgb;
    for (int c = 0; c < 3; ++c) rgb[c] = srgbToLinear(image.pixels[p * 4 + size_t(c)] / 255.0f);
    const glm::vec3 ycxcz = xyzToYcxcz(rgbToXyz(rgb));
    for (int c = 0; c < 3; ++c) opponent[size_t(c)].values[p] = ycxcz[c];
  }
  // One window for all channels, wide enough for the widest Gaussian (3 sigma).
  float widest = 0.0f;
  for (const Csf* csf : {&kCsfAchromatic, &kCsfRedGreen, &kCsfBlueYellow})
    for (int i = 0; i < 2; ++i)
      if (csf->a[size_t(i)] != 0.0f) widest = std::max(widest, csf->b[size_t(i)]);
  const int radius =
      int(std::ceil(3.0f * std::sqrt(widest / (2.0f * kPi * kPi)) * pixelsPerDegree));
  const Plane y = filterCsf(opponent[0], kCsfAchromatic, radius, pixelsPerDegree);
  const Plane cx = filterCsf(opponent[1], kCsfRedGreen, radius, pixelsPerDegree);
  const Plane cz = filterCsf(opponent[2], kCsfBlueYellow, radius, pixelsPerDegree);
  std::vector<glm::vec3> lab(count);
  for (size_t p = 0; p < count; ++p) {
    const glm::vec3 rgb = xyzToRgb(ycxczToXyz({y.values[p], cx.values[p], cz.values[p]}));
    lab[p] = huntLabOfLinear(glm::clamp(rgb, 0.0f, 1.0f));
  }
  return lab;
}

// Edge and point strength of the luminance Y / Yn (0..1): magnitudes of the
// gradient of first and of second Gaussian derivative filters, with sigma
// half the feature width. Each derivative kernel's positive weights sum to 1
// and its negative weights to -1.
struct Features {
  Plane edges, points;
};
Features detectFeatures(const ImageU8& image, float pixelsPerDegree) {
  const float sigma = 0.5f * kFeatureWidthDegrees * pixelsPerDegree;
  const int radius = int(std::ceil(3.0f * sigma));
  const std::vector<float> gaussian = gaussianKernel(sigma, radius);
  std::vector<float> first, second;
  for (int i = -radius; i <= radius; ++i) {
    const float x = float(i), g = std::exp(-x * x / (2.0f * sigma * sigma));
    first.push_back(-x * g);
    second.push_back((x * x / (sigma * sigma) - 1.0f) * g);
  }
  for (std::vector<float>* kernel : {&first, &second}) {
    float positive = 0.0f, negative = 0.0f;
    for (float w : *kernel) (w > 0.0f ? positive : negative) += w;
    for (float& w : *kernel) w = w > 0.0f ? w / positive : w / -negative;
  }
  Plane luminance(image.width, image.height);
  for (size_t p = 0; p < luminance.values.size(); ++p) {
    glm::vec3 rgb;
    for (int c = 0; c < 3; ++c) rgb[c] = srgbToLinear(image.pixels[p * 4 + size_t(c)] / 255.0f);
    luminance.values[p] = rgbToXyz(rgb).y / kWhite.y;
  }
  const Plane edgeX = convolveSeparable(luminance, first, gaussian);
  const Plane edgeY = convolveSeparable(luminance, gaussian, first);
  const Plane pointX = convolveSeparable(luminance, second, gaussian);
  const Plane pointY = convolveSeparable(luminance, gaussian, second);
  Features features{Plane(image.width, image.height), Plane(image.width, image.height)};
  for (size_t p = 0; p < luminance.values.size(); ++p) {
    features.edges.values[p] = std::hypot(edgeX.values[p], edgeY.values[p]);
    features.points.values[p] = std::hypot(pointX.values[p], pointY.values[p]);
  }
  return features;
}

}  // namespace

MetricMap flipError(const ImageU8& reference, const ImageU8& test, double pixelsPerDegree) {
  if (reference.width != test.width || reference.height != test.height)
    throw std::invalid_argument("flipError: sizes differ");
  const float ppd = float(pixelsPerDegree);
  const std::vector<glm::vec3> labReference = filteredLab(reference, ppd);
  const std::vector<glm::vec3> labTest = filteredLab(test, ppd);
  const Features featuresReference = detectFeatures(reference, ppd);
  const Features featuresTest = detectFeatures(test, ppd);
  // The largest colour difference: Hunt-adjusted green against blue.
  const float maxColour =
      std::pow(hyab(huntLabOfLinear({0.0f, 1.0f, 0.0f}), huntLabOfLinear({0.0f, 0.0f, 1.0f})), kQc);
  MetricMap map{reference.width, reference.height, std::vector<float>(labReference.size()), 0.0};
  double sum = 0.0;
  for (size_t p = 0; p < map.values.size(); ++p) {
    const float colour = std::pow(hyab(labReference[p], labTest[p]), kQc);
    // Small differences stretch over [0, pt), large ones compress into [pt, 1].
    float colourError =
        colour < kPc * maxColour
            ? kPt / (kPc * maxColour) * colour
            : kPt + (colour - kPc * maxColour) / (maxColour - kPc * maxColour) * (1.0f - kPt);
    colourError = std::clamp(colourError, 0.0f, 1.0f);
    const float edge = std::abs(featuresReference.edges.values[p] - featuresTest.edges.values[p]);
    const float point =
        std::abs(featuresReference.points.values[p] - featuresTest.points.values[p]);
    const float featureError =
        std::clamp(std::pow(std::max(edge, point) / std::sqrt(2.0f), kQf), 0.0f, 1.0f);
    map.values[p] = std::pow(colourError, 1.0f - featureError);
    sum += map.values[p];
  }
  map.mean = map.values.empty() ? 0.0 : sum / double(map.values.size());
  return map;
}

ImageU8 magmaHeatmap(const MetricMap& map) {
  // matplotlib's magma at 0, 1/8, ..., 1 (sRGB), interpolated linearly.
  static constexpr std::array<glm::vec3, 9> kAnchors = {
      glm::vec3(0, 0, 4),      glm::vec3(28, 16, 68),    glm::vec3(79, 18, 123),
      glm::vec3(129, 37, 129), glm::vec3(181, 54, 122),  glm::vec3(229, 80, 100),
      glm::vec3(251, 135, 97), glm::vec3(254, 194, 135), glm::vec3(252, 253, 191)};
  ImageU8 heat(map.width, map.height);
  for (size_t p = 0; p < map.values.size(); ++p) {
    const float v = std::clamp(std::isfinite(map.values[p]) ? map.values[p] : 1.0f, 0.0f, 1.0f);
    const float position = v * float(kAnchors.size() - 1);
    const size_t low = std::min(size_t(position), kAnchors.size() - 2);
    const glm::vec3 colour = glm::mix(kAnchors[low], kAnchors[low + 1], position - float(low));
    for (int c = 0; c < 3; ++c) heat.pixels[p * 4 + size_t(c)] = uint8_t(std::lround(colour[c]));
    heat.pixels[p * 4 + 3] = 255;
  }
  return heat;
}

}  // namespace shadelab
