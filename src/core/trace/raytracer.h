#pragma once
// The CPU Whitted ray tracer: the ground truth the rasterised modes are
// measured against. Same scene, same camera matrices, same illumination
// equation (core/scene/lighting.h, the twin of shaders/lighting.glsl), plus what a
// rasteriser cannot do: exact surfaces, shadows, mirror reflection and
// refraction.
//
//   I = local + (kr + kt F) I(reflected ray) + kt (1 - F) I(refracted ray)
//   local = emissive + Ia ka + sum over lights of k_shadow times the Phong terms
//
// F is the dielectric Fresnel reflectance by Schlick's approximation, the
// formula of the rasteriser's environment term (optics.h, environment.glsl),
// with the angle on the optically thinner side; 1 under total internal
// reflection. k_shadow, what a shadow ray lets through, is the product over
// every surface it crosses of kt (1 - F), F at the straight ray's angle to
// that surface seen from air: 0 behind an opaque surface. Shadow rays go
// straight (no refraction of light, as in Whitted 1980), so the light a
// glass ball focuses (a caustic) is never drawn. Surfaces are two-sided: a ray
// hitting the back of one sees it lit with the normal turned towards the ray.
// Textures (diffuse, normal and height maps) are sampled as the textured
// forward shaders sample them, filtered over the ray's footprint
// (core/trace/trace_material.h); rays that miss see the environment.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/base/image.h"
#include "core/scene/scene.h"
#include "core/trace/bvh.h"
#include "core/trace/ray.h"
#include "core/trace/trace_shapes.h"
#include "core/trace/trace_textures.h"

namespace shadelab {

struct TraceSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  // n * n stratified samples per pixel (1, 4, 9, 16, ...): the pixel cut into
  // an n x n grid, one sample per cell jittered by a hash of (pixel, sample),
  // so every run and every thread count draws the same pattern. spp 1 is
  // the pixel centre, where the rasteriser samples too. Box filter.
  uint32_t samplesPerPixel = 1;
  // Reflection/refraction bounces after the primary ray; 0 is local shading.
  uint32_t maxDepth = 5;
  uint32_t threads = 0;  // 0: one per hardware thread
  // New rays start this far off the surface (world units, times the largest
  // coordinate of the hit when that is above 1: float error grows with it),
  // on the side they leave towards, against self-intersection ("shadow
  // acne"); tests use 0.
  float epsilon = 1e-4f;
  // A secondary ray is not traced when its weight (product of kr and kt on
  // the way) falls below this: it cannot change an 8-bit pixel.
  float minContribution = 1.0f / 512.0f;
  bool blinn = false;   // Blinn-Phong (N.H)^n instead of Phong (R.V)^n
  bool shadows = true;  // false: every light reaches every surface, as in the rasteriser
  // false: no Fresnel term (F = 0 except under total internal reflection):
  // kr and kt are fixed weights and shadow rays pass kt per surface, as the
  // tracer did before issue 16; kept to measure what Fresnel changes.
  bool fresnel = true;
  // Called on the calling thread at each further hundredth of the rows done,
  // and with 1 at the end; empty: no reports.
  std::function<void(float fraction)> progress;
  // When set and it turns true, no further row is started and render()
  // returns early with the rows not reached left black (the viewer's
  // background reference, cancelled when the camera moves on).
  const std::atomic<bool>* cancel = nullptr;
};

struct TraceStats {
  uint64_t primaryRays = 0;
  uint64_t shadowRays = 0;
  uint64_t secondaryRays = 0;  // reflected and refracted
  uint64_t totalInternalReflections = 0;
  uint64_t total() const { return primaryRays + shadowRays + secondaryRays; }
  TraceStats& operator+=(const TraceStats& other);
};

struct TraceResult {
  ImageRgba image;  // linear RGBA, alpha 1
  TraceStats stats;
};

// What a ray found, in world space.
struct SurfaceHit {
  float t = 0.0f;
  glm::vec3 position{0.0f};
  glm::vec3 geometricNormal{0.0f};  // unit, facing the incoming ray
  glm::vec3 shadingNormal{0.0f};    // unit, interpolated on meshes, same side
  glm::vec2 uv{0.0f};               // as the object's mesh maps it (for textures)
  bool frontFace = true;            // the ray came from outside (against the outward normal)
  // Index into Scene::objects, or Scene::objects.size() + b for a copy of
  // Scene::billboards[b] (RayTracer::material gives either's material).
  uint32_t object = 0;
  // Object space, for texture coordinates: the point, the outward face
  // normal, and the triangle hit on a mesh.
  glm::vec3 localPosition{0.0f};
  glm::vec3 localNormal{0.0f};
  uint32_t triangle = 0;
};

// A ray's footprint as a cone (core/trace/trace_material.h): its width at the
// origin and how much that grows per unit of distance. The default, a
// line, samples textures at their finest level.
struct RayCone {
  float width = 0.0f;
  float spread = 0.0f;
};

// Camera rays exactly as the rasteriser projects: pixel (x, y) (0..width,
// row 0 at the top) unprojected through inverse(projection * view) of
// Camera::projectionMatrix(width / height) at depth 0 (near plane) and 1
// (far plane), for perspective, frustum and orthographic cameras alike.
// Each ray is that segment: 0 < t < 1. V at a camera ray's hit points to the
// eye, as in the rasteriser's eye space (also for orthographic cameras).
class CameraRays {
 public:
  CameraRays(const Camera& camera, uint32_t width, uint32_t height);
  Ray through(float x, float y) const;
  glm::vec3 viewer() const { return eye_; }

 private:
  glm::dmat4 clipToWorld_;
  glm::vec3 eye_;
  double width_, height_;
};

class RayTracer {
 public:
  // Builds one BVH per mesh that has no exact intersection (torus, teapot,
  // custom meshes). Procedural curved meshes are rebuilt at
  // `tessellationScale` times their tessellation first (up to 256k
  // triangles per mesh), so the reference is closer to the true surface
  // than the rasterised mesh. Billboards become the quads the rasteriser
  // draws for the scene's camera as it is now (core/scene/billboard_quad.h).
  // `scene` must outlive the tracer.
  explicit RayTracer(const Scene& scene, float tessellationScale = 4.0f);
  // A temporary scene would not: `RayTracer tracer(makeScene())` kept a
  // reference to a destroyed Scene (ASan: stack-use-after-scope when render
  // read its camera). Refused at compile time.
  explicit RayTracer(Scene&& scene, float tessellationScale = 4.0f) = delete;
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  // Throws InputError for an impossible size or a non-square sample count,
  // std::logic_error when the scene has billboards and its camera moved
  // since the tracer was built (they would face the old one).
  TraceResult render(const TraceSettings& settings) const;

  // The colour seen along `ray` for tMin < t < tMax. `viewer` is where V
  // points (the eye for camera rays, the origin for secondary ones), `depth`
  // the bounces already taken, `weight` the ray's share of the pixel,
  // `cone` its footprint for texture filtering. `cameraRay`: what the
  // camera sees straight on (a camera ray, or one through the uncovered
  // share of glTF BLEND surfaces), which passes the back faces the
  // rasteriser culls (intersect).
  // `layers`: the coverage surfaces already seen through on the way
  // (shade), which take no depth.
  glm::vec3 traceRay(const Ray& ray, float tMax, glm::vec3 viewer, uint32_t depth, float weight,
                     const TraceSettings& settings, TraceStats& stats, RayCone cone = {},
                     bool cameraRay = true, uint32_t layers = 0) const;
  // The nearest hit for tMin < t < tMax. A camera ray (`cameraRay`) passes
  // the back faces of single-sided surfaces, as the rasteriser culls them
  // (Material::doubleSided); reflected, refracted and shadow rays see both
  // sides, Whitted's surfaces having no counterpart in the rasteriser.
  std::optional<SurfaceHit> intersect(const Ray& ray, float tMin, float tMax,
                                      bool cameraRay = false) const;
  // k_shadow: the fraction of light passing from `origin` along `direction`
  // for 0 < t < tMax: 0 behind an opaque surface, otherwise the product over
  // the surfaces crossed of kt (1 - F), or of kt alone without `fresnel`.
  float transmittance(const Ray& ray, float tMax, bool fresnel = true) const;
  // The material of the object or billboard hit, before its textures.
  const Material& material(const SurfaceHit& hit) const;

 private:
  struct TracedObject;
  const TracedObject& tracedObject(uint32_t sceneObject) const;
  // The object's nearest hit in (tMin, tMax) that a glTF MASK cut-out keeps
  // (cutAway, trace_material.h) and, with `cullBackFaces`, that is not the
  // back face of a single-sided surface the rasteriser culls (opaque or glTF
  // BLEND coverage: glass keeps the back faces rays leave it by); false if none.
  bool nearestKeptHit(const TracedObject& object, const Ray& local, float tMin, float tMax,
                      bool cullBackFaces, LocalHit& hit, glm::vec3& geometric) const;
  glm::vec3 shade(const Ray& ray, SurfaceHit hit, glm::vec3 viewer, uint32_t depth, float weight,
                  const TraceSettings& settings, TraceStats& stats, RayCone cone, bool cameraRay,
                  uint32_t layers) const;
  // The material of `object` (the one hit) with its textures applied (the
  // diffuse texel, the bumped shading normal written into `hit`), filtered
  // over `footprint`.
  Material materialAt(const Ray& ray, const TracedObject& object, SurfaceHit& hit,
                      float footprint) const;
  glm::vec3 localShading(const SurfaceHit& hit, const Material& material, bool receivesShadows,
                         glm::vec3 viewer, const TraceSettings& settings, TraceStats& stats) const;
  Ray offsetRay(const SurfaceHit& hit, glm::vec3 direction, float epsilon) const;
  glm::vec3 tracePixel(const CameraRays& camera, uint32_t x, uint32_t y, uint32_t grid,
                       const TraceSettings& settings, TraceStats& stats) const;

  const Scene& scene_;
  // The camera's view when the tracer was built: billboards turn towards it.
  glm::mat4 billboardView_;
  std::vector<Material> billboardMaterials_;   // by traced billboard, reserved up front
  std::vector<std::unique_ptr<Mesh>> meshes_;  // the meshes the BVHs were built from
  std::vector<std::unique_ptr<Bvh>> bvhs_;
  std::vector<TracedObject> objects_;
  std::vector<TraceTexture> textures_;  // parallel to Scene::textures
};

// A billboard's material as the tracer applies it, billboard.frag's
// equation: cut out at the diffuse texel's alpha (BillboardAlpha::Test) or
// covering the texel's alpha times 1 - transparency of the pixel (Blend),
// two-sided, with no mirror or environment term.
Material billboardMaterial(const Billboard& billboard);

// Throws InputError unless `samplesPerPixel` is a square n * n, 1..256; the
// message begins with `name` (the command line passes its option, "--spp").
void checkSamplesPerPixel(uint32_t samplesPerPixel, const std::string& name = "samples per pixel");

// The colour of a ray that hits nothing: the environment's radiance along
// it (core/scene/environment.h, the same orientation and intensity the cube map
// is built with), or the background colour in a scene without one.
glm::vec3 missColour(const Scene& scene, glm::vec3 direction);

}  // namespace shadelab
