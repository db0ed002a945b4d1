#include "measure/bump_silhouette.h"

#include <cassert>
#include <cmath>

#include "core/metrics/metrics.h"
#include "core/trace/trace_textures.h"

namespace shadelab {
namespace {

// A pixel shows the sphere where it differs from the clear colour.
bool covered(const ImageRgba& image, const Scene& scene, uint32_t x, uint32_t y) {
  const glm::vec4 c = image.at(x, y);
  return glm::length(glm::vec3(c) - scene.background) > 1e-3f;
}

}  // namespace

Scene bumpSphereScene() {
  Scene scene = builtinScene("bump");
  std::erase_if(scene.objects, [](const Object& object) { return object.name != "sphere"; });
  assert(scene.objects.size() == 1 && scene.objects[0].material.heightMap.present());
  return scene;
}

float bumpDisplacementAmplitude(const Scene& bumpSphere) {
  const Object& sphere = bumpSphere.objects[0];
  const Material& material = sphere.material;
  const Texture& height = bumpSphere.textures[size_t(material.heightMap.texture)];
  const float radius = bumpSphere.shapes[sphere.mesh].radius;
  // Around the equator u runs once over 2 pi r: uvScale.x * width texels.
  const float texel = 2.0f * float(M_PI) * radius / (material.uvScale.x * float(height.width));
  return material.bumpScale * texel;
}

Scene displacedSphereScene(const Scene& bumpSphere, uint32_t slices) {
  Scene scene = bumpSphere;
  Object& sphere = scene.objects[0];
  ShapeDesc shape = scene.shapes[sphere.mesh];
  shape.tessellation = slices;
  Mesh mesh = buildShape(shape);
  const Material& material = sphere.material;
  const TraceTexture height(scene.textures[size_t(material.heightMap.texture)]);
  const float amplitude = bumpDisplacementAmplitude(bumpSphere);
  for (Vertex& vertex : mesh.vertices) {
    // st as texturing.glsl computes it: t = 1 - v (rows stored top first).
    const glm::vec2 st{vertex.uv.x * material.uvScale.x, 1.0f - vertex.uv.y * material.uvScale.y};
    const float h = height.sample(st, 0.0f, material.heightMap.sampler).r;
    vertex.position += glm::normalize(vertex.normal) * amplitude * (h - 1.0f);
  }
  computeNormals(mesh);
  sphere.mesh = scene.addMesh(std::move(mesh));
  sphere.material.heightMap = {};
  return scene;
}

BumpSilhouetteMeasurement measureBumpSilhouette(Renderer& renderer, uint32_t slices, uint32_t width,
                                                uint32_t height) {
  const Scene bump = bumpSphereScene();
  const Scene displaced = displacedSphereScene(bump, slices);
  Scene plain = bump;
  plain.objects[0].material.heightMap = {};
  const RenderSettings settings{width, height, ShadingModel::Phong};
  BumpSilhouetteMeasurement result;
  result.slices = slices;
  result.triangles = displaced.meshes[displaced.objects[0].mesh].triangleCount();
  result.bump = renderer.renderToImage(bump, settings).image;
  result.displaced = renderer.renderToImage(displaced, settings).image;
  const ImageRgba plainImage = renderer.renderToImage(plain, settings).image;
  const MetricMap flip = flipError(encodeSrgb8(result.displaced), encodeSrgb8(result.bump));
  double flipSum = 0.0;
  uint64_t both = 0;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const bool b = covered(result.bump, bump, x, y);
      const bool d = covered(result.displaced, bump, x, y);
      const bool p = covered(plainImage, bump, x, y);
      result.coveredBump += b;
      result.coveredDisplaced += d;
      result.coveredPlain += p;
      result.silhouetteDifference += b != d;
      result.bumpVersusPlain += b != p;
      if (b && d) {
        flipSum += flip.at(x, y);
        ++both;
      }
    }
  result.interiorFlip = both ? flipSum / double(both) : 0.0;
  return result;
}

}  // namespace shadelab
