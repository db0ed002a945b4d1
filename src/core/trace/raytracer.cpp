#include "core/trace/raytracer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <thread>

#include "core/base/errors.h"
#include "core/scene/billboard_quad.h"
#include "core/scene/lighting.h"
#include "core/scene/transform.h"
#include "core/scene/uv_mapping.h"
#include "core/trace/optics.h"
#include "core/trace/trace_material.h"
#include "core/trace/trace_shapes.h"
#include "interface.h"

namespace shadelab {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Past this, a finer tessellation costs more BVH build time than it removes
// error: 256k triangles are far below a pixel at any size we trace.
constexpr size_t kMaxTracedTriangles = 1u << 18;

enum class Surface { Sphere, Plane, Box, Mesh };

Surface surfaceOf(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::UvSphere:
    case ShapeKind::Icosphere:
      return Surface::Sphere;
    case ShapeKind::Plane:
      return Surface::Plane;
    case ShapeKind::Box:
      return Surface::Box;
    default:
      return Surface::Mesh;
  }
}

// Wellons' "lowbias32" integer hash: a fixed, well-mixed function of the
// pixel and sample, so sample positions never depend on thread scheduling.
uint32_t mixBits(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float jitter(uint32_t x, uint32_t y, uint32_t sample, uint32_t dimension) {
  uint32_t h = mixBits(x ^ mixBits(y ^ mixBits(sample * 2u + dimension)));
  return float(h >> 8) * (1.0f / 16777216.0f);  // 24 bits: uniform in [0, 1)
}

Bounds transformBounds(const Bounds& box, const glm::mat4& transform) {
  Bounds result{glm::vec3(kInfinity), glm::vec3(-kInfinity)};
  for (int corner = 0; corner < 8; ++corner) {
    glm::vec3 local{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                    corner & 4 ? box.max.z : box.min.z};
    glm::vec3 world = glm::vec3(transform * glm::vec4(local, 1.0f));
    result.min = glm::min(result.min, world);
    result.max = glm::max(result.max, world);
  }
  return result;
}

}  // namespace

TraceStats& TraceStats::operator+=(const TraceStats& other) {
  primaryRays += other.primaryRays;
  shadowRays += other.shadowRays;
  secondaryRays += other.secondaryRays;
  totalInternalReflections += other.totalInternalReflections;
  return *this;
}

glm::vec3 missColour(const Scene& scene, glm::vec3 direction) {
  return scene.environment.present() ? environmentRadiance(scene.environment, direction)
                                     : scene.background;
}

CameraRays::CameraRays(const Camera& camera, uint32_t width, uint32_t height)
    : eye_(camera.eye), width_(width), height_(height) {
  // The reversed-Z projection (near at depth 1, far at 0): the usual one
  // keeps far / (near - far) in a float, which rounds to -1 once far / near
  // passes about 1e7, and its inverse then throws the rays away (a blank
  // trace of a camera with near 1e-5 and far 100, which the rasteriser drew).
  const glm::mat4 clip =
      camera.projectionMatrix(float(width) / float(height), true) * camera.viewMatrix();
  clipToWorld_ = glm::inverse(glm::dmat4(clip));
}

Ray CameraRays::through(float x, float y) const {
  const double ndcX = 2.0 * double(x) / width_ - 1.0;
  const double ndcY = 2.0 * double(y) / height_ - 1.0;  // Vulkan: y down, like the rows
  glm::dvec4 nearPoint = clipToWorld_ * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
  glm::dvec4 farPoint = clipToWorld_ * glm::dvec4(ndcX, ndcY, 0.0, 1.0);
  const glm::dvec3 origin = glm::dvec3(nearPoint) / nearPoint.w;
  const glm::dvec3 end = glm::dvec3(farPoint) / farPoint.w;
  return {glm::vec3(origin), glm::vec3(end - origin)};
}

struct RayTracer::TracedObject {
  Surface surface = Surface::Mesh;
  float radius = 1.0f;          // sphere
  float size = 1.0f;            // plane
  glm::vec3 halfExtents{0.5f};  // box
  const Mesh* mesh = nullptr;   // mesh
  const Bvh* bvh = nullptr;     // mesh
  // A mirroring transform's mesh is wound the other way (Object::transform):
  // its triangles' cross products point inwards in object space.
  bool mirrored = false;
  glm::mat4 worldToObject{1.0f};
  glm::mat3 normalToWorld{1.0f};  // inverse transpose of the transform's 3x3
  Bounds worldBounds;
  float transparency = 0.0f;
  float ior = 1.5f;
  bool castsShadows = true;    // Object::castsShadows: shadow rays pass through it when false
  bool alphaCoverage = false;  // Material::alphaCoverage: shadow rays pass kt, no Fresnel
  bool receivesShadows = true;
  // SurfaceHit::object's numbering: Scene::objects, then Scene::billboards.
  uint32_t sceneObject = 0;
  const Material* material = nullptr;  // the scene object's, or billboardMaterial's
  UvProjection projection = UvProjection::Mesh;
  Bounds uvBounds;  // the scene mesh's box, which S-mappings are fitted to (as at upload)

  Ray toLocal(const Ray& ray) const {
    return {glm::vec3(worldToObject * glm::vec4(ray.origin, 1.0f)),
            glm::mat3(worldToObject) * ray.direction};
  }
  // Object-space hit; `geometric` is the unnormalised outward face normal.
  // `cullBackFaces`: surfaces facing away from the ray are passed (a mesh's
  // triangles in the BVH, so a coincident front face is still found).
  bool intersect(const Ray& local, float tMin, float tMax, LocalHit& hit, glm::vec3& geometric,
                 bool cullBackFaces = false) const;
  uint32_t countHits(const Ray& local, float tMax) const;
  // Calls visit(n) with the outward normal (object space, not normalised) at
  // each crossing with 0 < t < tMax.
  void forEachCrossingNormal(const Ray& local, float tMax,
                             const std::function<void(glm::vec3)>& visit) const;
  // The texture coordinates at an object-space point on (or, linearly
  // extended, near) the surface hit with `normal` on `triangle`.
  glm::vec2 uvAt(glm::vec3 point, glm::vec3 normal, uint32_t triangle) const;
  // The texture coordinates of `hit` on `local` (materialAt's).
  glm::vec2 hitUv(const Ray& local, const LocalHit& hit, glm::vec3 geometric) const {
    return projection == UvProjection::Mesh ? hit.uv
                                            : uvAt(local.at(hit.t), geometric, hit.triangle);
  }
};

namespace {
// glTF alphaMode MASK: a ray passes through at most this many cut-away
// layers of one object before the object counts as missed.
constexpr int kMaxCutAwayLayers = 1024;
// Coverage surfaces (glTF BLEND, blended billboards) a ray sees through
// before what lies further is left black: each is a level of recursion.
constexpr uint32_t kMaxCoverageLayers = 256;
}  // namespace

glm::vec2 RayTracer::TracedObject::uvAt(glm::vec3 point, glm::vec3 normal,
                                        uint32_t triangle) const {
  if (projection != UvProjection::Mesh) return projectUv(projection, point, normal, uvBounds);
  switch (surface) {
    case Surface::Sphere:
      return sphericalUv(point / glm::length(point));
    case Surface::Plane:
      return planeUv(point, size);
    case Surface::Box:
      return boxFaceUv(point, halfExtents, normal);
    case Surface::Mesh:
      return triangleUv(point, mesh->vertices[mesh->indices[3 * triangle]],
                        mesh->vertices[mesh->indices[3 * triangle + 1]],
                        mesh->vertices[mesh->indices[3 * triangle + 2]]);
  }
  return glm::vec2(0.0f);
}

bool RayTracer::TracedObject::intersect(const Ray& local, float tMin, float tMax, LocalHit& hit,
                                        glm::vec3& geometric, bool cullBackFaces) const {
  if (cullBackFaces && surface != Surface::Mesh) {
    // A sphere, plane or box crosses a line at most twice: past a back
    // face, the next crossing.
    for (int crossing = 0; crossing < 2; ++crossing) {
      if (!intersect(local, tMin, tMax, hit, geometric)) return false;
      if (glm::dot(local.direction, geometric) <= 0.0f) return true;
      tMin = std::nextafter(hit.t, kInfinity);
    }
    return false;
  }
  bool found = false;
  switch (surface) {
    case Surface::Sphere:
      found = intersectSphere(local, radius, tMin, tMax, hit);
      break;
    case Surface::Plane:
      found = intersectPlane(local, size, tMin, tMax, hit);
      break;
    case Surface::Box:
      found = intersectBox(local, halfExtents, tMin, tMax, hit);
      break;
    case Surface::Mesh: {
      TriangleHit triangle;
      const float cullFacing = cullBackFaces ? (mirrored ? -1.0f : 1.0f) : 0.0f;
      if (!bvh->intersect(local, tMin, tMax, triangle, cullFacing)) return false;
      const Vertex& a = mesh->vertices[mesh->indices[3 * triangle.triangle]];
      const Vertex& b = mesh->vertices[mesh->indices[3 * triangle.triangle + 1]];
      const Vertex& c = mesh->vertices[mesh->indices[3 * triangle.triangle + 2]];
      const float w = 1.0f - triangle.u - triangle.v;
      hit.t = triangle.t;
      hit.normal = w * a.normal + triangle.u * b.normal + triangle.v * c.normal;
      hit.uv = w * a.uv + triangle.u * b.uv + triangle.v * c.uv;
      hit.triangle = triangle.triangle;
      geometric = glm::cross(b.position - a.position, c.position - a.position);
      if (mirrored) geometric = -geometric;
      return true;
    }
  }
  geometric = hit.normal;
  return found;
}

uint32_t RayTracer::TracedObject::countHits(const Ray& local, float tMax) const {
  switch (surface) {
    case Surface::Sphere:
      return countInRange(sphereCrossings(local, radius), 0.0f, tMax);
    case Surface::Plane:
      return countInRange(planeCrossings(local, size), 0.0f, tMax);
    case Surface::Box:
      return countInRange(boxCrossings(local, halfExtents), 0.0f, tMax);
    case Surface::Mesh:
      return bvh->countHits(local, 0.0f, tMax);
  }
  return 0;
}

void RayTracer::TracedObject::forEachCrossingNormal(
    const Ray& local, float tMax, const std::function<void(glm::vec3)>& visit) const {
  Crossings crossings;
  switch (surface) {
    case Surface::Sphere:
      crossings = sphereCrossings(local, radius);
      break;
    case Surface::Plane:
      crossings = planeCrossings(local, size);
      break;
    case Surface::Box:
      crossings = boxCrossings(local, halfExtents);
      break;
    case Surface::Mesh:
      if (mirrored)
        bvh->forEachHitNormal(local, 0.0f, tMax, [&](glm::vec3 normal) { visit(-normal); });
      else
        bvh->forEachHitNormal(local, 0.0f, tMax, visit);
      return;
  }
  for (int i = 0; i < crossings.count; ++i) {
    if (!(crossings.t[i] > 0.0f && crossings.t[i] < tMax)) continue;
    const glm::vec3 point = local.at(crossings.t[i]);
    if (surface == Surface::Sphere) {
      visit(point);
    } else if (surface == Surface::Plane) {
      visit({0.0f, 1.0f, 0.0f});
    } else {  // the box face whose slab the point is on
      const glm::vec3 relative = glm::abs(point) / halfExtents;
      const int axis = relative.x >= relative.y && relative.x >= relative.z ? 0
                       : relative.y >= relative.z                           ? 1
                                                                            : 2;
      glm::vec3 normal{0.0f};
      normal[axis] = 1.0f;
      visit(normal);
    }
  }
}

RayTracer::RayTracer(const Scene& scene, float tessellationScale)
    : scene_(scene), billboardView_(scene.camera.viewMatrix()) {
  std::vector<const Bvh*> meshBvh(scene.meshes.size(), nullptr);
  std::vector<const Mesh*> meshSource(scene.meshes.size(), nullptr);
  for (const Object& object : scene.objects) {
    const ShapeDesc& shape = scene.shapes[object.mesh];
    if (surfaceOf(shape.kind) != Surface::Mesh || meshBvh[object.mesh]) continue;
    // Segments grow with the scale on both parameters, triangles with its
    // square: stop where a mesh would pass kMaxTracedTriangles.
    const float triangles = float(std::max<size_t>(1, scene.meshes[object.mesh].triangleCount()));
    const float scale =
        std::clamp(std::sqrt(float(kMaxTracedTriangles) / triangles), 1.0f, tessellationScale);
    meshes_.push_back(std::make_unique<Mesh>(
        shape.kind == ShapeKind::Custom ? scene.meshes[object.mesh] : buildShape(shape, scale)));
    bvhs_.push_back(std::make_unique<Bvh>(*meshes_.back()));
    meshBvh[object.mesh] = bvhs_.back().get();
    meshSource[object.mesh] = meshes_.back().get();
  }
  for (uint32_t index = 0; index < scene.objects.size(); ++index) {
    const Object& object = scene.objects[index];
    const ShapeDesc& shape = scene.shapes[object.mesh];
    // A collapsed (zero-scale) or non-finite transform has no inverse: the
    // object is drawn as nothing, as the rasteriser's degenerate triangles are.
    const float determinant = glm::determinant(glm::mat3(object.transform));
    if (!(std::abs(determinant) > 1e-30f) || !std::isfinite(determinant)) continue;
    TracedObject traced;
    traced.sceneObject = index;
    traced.surface = surfaceOf(shape.kind);
    traced.radius = shape.radius;
    traced.size = shape.size;
    traced.halfExtents = shape.halfExtents;
    traced.mesh = meshSource[object.mesh];
    traced.bvh = meshBvh[object.mesh];
    traced.mirrored = mirrors(object.transform);
    traced.worldToObject = glm::inverse(object.transform);
    traced.normalToWorld = glm::transpose(glm::inverse(glm::mat3(object.transform)));
    traced.transparency = object.material.transparency;
    traced.ior = object.material.ior;
    traced.castsShadows = object.castsShadows;
    traced.alphaCoverage = object.material.alphaCoverage;
    traced.receivesShadows = object.receivesShadows;
    traced.material = &object.material;
    traced.projection = object.material.uvProjection;
    if (traced.projection != UvProjection::Mesh)
      traced.uvBounds = computeBounds(scene.meshes[object.mesh]);
    Bounds local;
    switch (traced.surface) {
      case Surface::Sphere:
        local = {glm::vec3(-shape.radius), glm::vec3(shape.radius)};
        break;
      case Surface::Plane:
        local = {{-0.5f * shape.size, 0.0f, -0.5f * shape.size},
                 {0.5f * shape.size, 0.0f, 0.5f * shape.size}};
        break;
      case Surface::Box:
        local = {-shape.halfExtents, shape.halfExtents};
        break;
      case Surface::Mesh:
        local = traced.bvh->bounds();
        break;
    }
    traced.worldBounds = transformBounds(local, object.transform);
    objects_.push_back(traced);
  }
  // Billboards: the quads the rasterised frame of this camera draws, one
  // mesh per billboard object, in world space. They cast no shadow, as in
  // the rasteriser (shadow_pass.h).
  billboardMaterials_.reserve(scene.billboards.size());
  for (uint32_t b = 0; b < scene.billboards.size(); ++b) {
    const Billboard& billboard = scene.billboards[b];
    if (billboard.instances.empty()) continue;
    meshes_.push_back(std::make_unique<Mesh>(billboardQuads(billboard, billboardView_)));
    bvhs_.push_back(std::make_unique<Bvh>(*meshes_.back()));
    billboardMaterials_.push_back(billboardMaterial(billboard));
    TracedObject traced;
    traced.sceneObject = uint32_t(scene.objects.size()) + b;
    traced.surface = Surface::Mesh;
    traced.mesh = meshes_.back().get();
    traced.bvh = bvhs_.back().get();
    traced.material = &billboardMaterials_.back();
    traced.transparency = traced.material->transparency;
    traced.alphaCoverage = traced.material->alphaCoverage;
    traced.castsShadows = false;
    traced.receivesShadows = billboard.receivesShadows;
    traced.worldBounds = traced.bvh->bounds();
    objects_.push_back(traced);
  }
  for (const Texture& texture : scene.textures) textures_.emplace_back(texture);
}

RayTracer::~RayTracer() = default;

Material billboardMaterial(const Billboard& billboard) {
  Material material = billboard.material;
  material.reflectivity = 0.0f;  // billboard.frag has no mirror or environment term
  material.doubleSided = true;   // not culled; the back lit as the front
  material.uvProjection = UvProjection::Mesh;
  material.alpha = 1.0f;
  if (billboard.alpha == BillboardAlpha::Blend) {
    material.alphaCoverage = true;  // the texel's alpha times 1 - transparency
    material.alphaCutoff = 0.0f;
  } else {
    material.alphaCoverage = false;  // cut out, otherwise opaque
    material.transparency = 0.0f;
  }
  return material;
}

bool RayTracer::nearestKeptHit(const TracedObject& object, const Ray& local, float tMin, float tMax,
                               bool cullBackFaces, LocalHit& hit, glm::vec3& geometric) const {
  const Material& material = *object.material;
  const bool culled = cullBackFaces && !material.doubleSided &&
                      (object.transparency <= 0.0f || object.alphaCoverage);
  for (int layer = 0; layer < kMaxCutAwayLayers; ++layer) {
    if (!object.intersect(local, tMin, tMax, hit, geometric, culled)) return false;
    if (!cutAway(material, textures_, object.hitUv(local, hit, geometric))) return true;
    tMin = std::nextafter(hit.t, kInfinity);
  }
  return false;
}

std::optional<SurfaceHit> RayTracer::intersect(const Ray& ray, float tMin, float tMax,
                                               bool cameraRay) const {
  const glm::vec3 inverse = 1.0f / ray.direction;
  LocalHit best;
  glm::vec3 bestGeometric{0.0f};
  int bestObject = -1;
  Ray bestLocal;
  for (size_t i = 0; i < objects_.size(); ++i) {
    const TracedObject& object = objects_[i];
    float tEntry;
    if (!intersectBounds(object.worldBounds, ray, inverse, tMin, tMax, tEntry)) continue;
    LocalHit hit;
    glm::vec3 geometric;
    const Ray local = object.toLocal(ray);
    if (!nearestKeptHit(object, local, tMin, tMax, cameraRay, hit, geometric)) continue;
    best = hit;
    bestLocal = local;
    bestGeometric = geometric;
    bestObject = int(i);
    tMax = hit.t;
  }
  if (bestObject < 0) return std::nullopt;
  const TracedObject& object = objects_[size_t(bestObject)];
  SurfaceHit hit;
  hit.t = best.t;
  hit.object = object.sceneObject;
  hit.position = ray.at(best.t);
  hit.uv = best.uv;
  hit.localPosition = bestLocal.at(best.t);
  hit.localNormal = bestGeometric;
  hit.triangle = best.triangle;
  glm::vec3 geometric = object.normalToWorld * bestGeometric;
  glm::vec3 shading = object.normalToWorld * best.normal;
  const float geometricLength = glm::length(geometric);
  const float shadingLength = glm::length(shading);
  geometric = geometricLength > 0.0f ? geometric / geometricLength : -glm::normalize(ray.direction);
  shading = shadingLength > 0.0f ? shading / shadingLength : geometric;
  hit.frontFace = glm::dot(ray.direction, geometric) <= 0.0f;
  const float side = hit.frontFace ? 1.0f : -1.0f;
  hit.geometricNormal = side * geometric;
  hit.shadingNormal = side * shading;
  return hit;
}

float RayTracer::transmittance(const Ray& ray, float tMax, bool fresnel) const {
  const glm::vec3 inverse = 1.0f / ray.direction;
  const glm::vec3 unit = glm::normalize(ray.direction);
  float passed = 1.0f;
  for (const TracedObject& object : objects_) {
    if (!object.castsShadows) continue;
    float tEntry;
    if (!intersectBounds(object.worldBounds, ray, inverse, 0.0f, tMax, tEntry)) continue;
    const Ray local = object.toLocal(ray);
    if (object.material->alphaCutoff > 0.0f) {
      // A cut-out: each crossing the cut keeps blocks (or passes kt).
      LocalHit hit;
      glm::vec3 geometric;
      // Shadow rays see both faces, as the shadow maps draw both.
      for (float from = 0.0f; nearestKeptHit(object, local, from, tMax, false, hit, geometric);
           from = std::nextafter(hit.t, kInfinity)) {
        if (object.transparency <= 0.0f) return 0.0f;
        passed *= object.transparency;
      }
      continue;
    }
    if (object.alphaCoverage && object.material->diffuseMap.present()) {
      // glTF BLEND over a texture: each crossing passes what its texel
      // leaves uncovered (a leaf card's holes let the light through).
      LocalHit hit;
      glm::vec3 geometric;
      for (float from = 0.0f; nearestKeptHit(object, local, from, tMax, false, hit, geometric);
           from = std::nextafter(hit.t, kInfinity)) {
        passed *= 1.0f - coverage(*object.material, textures_, object.hitUv(local, hit, geometric));
        if (passed <= 0.0f) return 0.0f;
      }
      continue;
    }
    if (!fresnel || object.transparency <= 0.0f || object.alphaCoverage) {
      const uint32_t crossings = object.countHits(local, tMax);
      if (crossings == 0) continue;
      if (object.transparency <= 0.0f) return 0.0f;
      passed *= std::pow(object.transparency, float(crossings));
      continue;
    }
    // The straight shadow ray does not refract, so each crossing is weighed
    // as light arriving from air at the ray's angle to the surface: for a
    // sphere, entry and exit see the same angle, as the refracted path would.
    object.forEachCrossingNormal(local, tMax, [&](glm::vec3 normal) {
      const glm::vec3 world = object.normalToWorld * normal;
      const float length = glm::length(world);
      const float cosine = length > 0.0f ? std::abs(glm::dot(world / length, unit)) : 1.0f;
      passed *= object.transparency * (1.0f - schlickFresnel(cosine, 1.0f, object.ior));
    });
  }
  return passed;
}

Ray RayTracer::offsetRay(const SurfaceHit& hit, glm::vec3 direction, float epsilon) const {
  const float side = glm::dot(direction, hit.geometricNormal) >= 0.0f ? 1.0f : -1.0f;
  // Rounding error grows with the coordinates' magnitude, so does the offset.
  const glm::vec3 magnitude = glm::abs(hit.position);
  const float scale = std::max({1.0f, magnitude.x, magnitude.y, magnitude.z});
  return {hit.position + side * epsilon * scale * hit.geometricNormal, direction};
}

// Phong at the hit with the unshadowed lights only, moved so the viewer sits
// at the origin, which is where lighting.cpp (like the shader's eye space)
// takes V from. At most MAX_LIGHTS, as the shaders see.
glm::vec3 RayTracer::localShading(const SurfaceHit& hit, const Material& material,
                                  bool receivesShadows, glm::vec3 viewer,
                                  const TraceSettings& settings, TraceStats& stats) const {
  std::array<Light, MAX_LIGHTS> lit;
  uint32_t visible = 0;
  const size_t count = std::min<size_t>(scene_.lights.size(), MAX_LIGHTS);
  for (size_t i = 0; i < count; ++i) {
    const Light& light = scene_.lights[i];
    const bool point = light.type == LightType::Point;
    glm::vec3 toLight = point ? light.position - hit.position : -light.direction;
    if (!point) {
      const float length = glm::length(toLight);
      if (!(length > 0.0f)) continue;
      toLight /= length;
    }
    // The equation adds nothing where N.L <= 0: no shadow ray needed there.
    if (!(glm::dot(toLight, hit.shadingNormal) > 0.0f)) continue;
    float passed = 1.0f;
    // The scene's switches, as the shadow maps obey them: a light with
    // "shadows": false, an object that receives none.
    if (settings.shadows && light.shadows && receivesShadows) {
      Ray shadow = offsetRay(hit, toLight, settings.epsilon);
      if (point) shadow.direction = light.position - shadow.origin;  // the segment is 0 < t < 1
      ++stats.shadowRays;
      passed = transmittance(shadow, point ? 1.0f : kInfinity, settings.fresnel);
      if (passed <= 0.0f) continue;
    }
    Light& out = lit[visible++];
    out.type = light.type;
    out.position = light.position - viewer;
    out.direction = -toLight;  // unit length
    out.intensity = passed * light.intensity;
    out.attenuation = light.attenuation;
  }
  return material.emissive + illuminate(scene_.ambient, std::span(lit.data(), visible),
                                        hit.position - viewer, hit.shadingNormal, material,
                                        settings.blinn);
}

const RayTracer::TracedObject& RayTracer::tracedObject(uint32_t sceneObject) const {
  // objects_ is in SurfaceHit::object's order, some objects left out.
  const auto found = std::lower_bound(
      objects_.begin(), objects_.end(), sceneObject,
      [](const TracedObject& traced, uint32_t index) { return traced.sceneObject < index; });
  assert(found != objects_.end() && found->sceneObject == sceneObject);
  return *found;
}

const Material& RayTracer::material(const SurfaceHit& hit) const {
  return *tracedObject(hit.object).material;
}

Material RayTracer::materialAt(const Ray& ray, const TracedObject& object, SurfaceHit& hit,
                               float footprint) const {
  const Material& material = *object.material;
  if (!material.diffuseMap.present() && !material.normalMap.present() &&
      !material.heightMap.present())
    return material;
  const glm::vec3 incident = glm::normalize(ray.direction);
  UvFrame frame;
  frame.uv = object.projection == UvProjection::Mesh
                 ? hit.uv
                 : object.uvAt(hit.localPosition, hit.localNormal, hit.triangle);
  tangentPlaneAxes(hit.geometricNormal, incident, frame.along, frame.across);
  // The uv's derivatives by central differences a small step either side
  // (exact for the linear mappings, within float rounding for the rest).
  const Bounds& box = object.worldBounds;
  const float step = 1e-4f * std::max(1.0f, glm::length(box.max - box.min));
  const glm::mat3 toLocal(object.worldToObject);
  auto derivative = [&](glm::vec3 axis) {
    const glm::vec3 offset = toLocal * (step * axis);
    glm::vec2 difference = object.uvAt(hit.localPosition + offset, hit.localNormal, hit.triangle) -
                           object.uvAt(hit.localPosition - offset, hit.localNormal, hit.triangle);
    difference.x -= std::round(difference.x);  // u jumps by 1 across a seam
    return difference / (2.0f * step);
  };
  frame.uvPerAlong = derivative(frame.along);
  frame.uvPerAcross = derivative(frame.across);
  const float cosine = std::abs(glm::dot(hit.geometricNormal, incident));
  // The bumped normal is the surface's: found for its front and turned
  // with it, as the shaders negate the bumped normal of a back face.
  const float side = hit.frontFace ? 1.0f : -1.0f;
  glm::vec3 normal = side * hit.shadingNormal;
  Material textured = texturedMaterial(material, textures_, frame, footprint, cosine, normal);
  hit.shadingNormal = side * normal;
  return textured;
}

glm::vec3 RayTracer::shade(const Ray& ray, SurfaceHit hit, glm::vec3 viewer, uint32_t depth,
                           float weight, const TraceSettings& settings, TraceStats& stats,
                           RayCone cone, bool cameraRay, uint32_t layers) const {
  const float footprint = cone.width + cone.spread * hit.t * glm::length(ray.direction);
  const RayCone next{footprint, cone.spread};
  // Looked up once per hit (a binary search over the objects).
  const TracedObject& object = tracedObject(hit.object);
  const Material material = materialAt(ray, object, hit, footprint);
  glm::vec3 colour = localShading(hit, material, object.receivesShadows, viewer, settings, stats);
  const float kr = material.reflectivity, kt = material.transparency;
  const glm::vec3 incident = glm::normalize(ray.direction);
  if (material.alphaCoverage) {
    // Coverage (glTF BLEND, blended billboards): the surface fills 1 - kt of
    // the pixel and the rest is what lies behind it, seen straight on. That
    // is no bounce: it takes no depth, so stacked cards (trees behind trees)
    // and --bounces 0 show what the rasteriser's blend shows, up to
    // kMaxCoverageLayers surfaces deep.
    colour *= 1.0f - kt;
    if (kt > 0.0f && weight * kt >= settings.minContribution && layers < kMaxCoverageLayers) {
      const Ray behind = offsetRay(hit, incident, settings.epsilon);
      colour += kt * traceRay(behind, kInfinity, behind.origin, depth, weight * kt, settings, stats,
                              next, cameraRay, layers + 1);
    }
  }
  if (depth >= settings.maxDepth) return colour;
  // Of the transmitted share kt, the Fresnel reflectance F goes along the
  // mirror direction and 1 - F is refracted; total internal reflection
  // (F = 1) sends all of it back inside. Entering the object from air
  // (eta = 1 / ior) or leaving it (ior / 1), by the side the ray arrived on.
  std::optional<glm::vec3> refracted;
  float fresnel = 0.0f;
  if (kt > 0.0f && !material.alphaCoverage) {
    const float eta = hit.frontFace ? 1.0f / material.ior : material.ior;
    refracted = refractDirection(incident, hit.shadingNormal, eta);
    if (!refracted) {
      ++stats.totalInternalReflections;
      fresnel = 1.0f;
    } else if (settings.fresnel) {
      const float outside = 1.0f, inside = material.ior;
      fresnel = schlickFresnel(glm::dot(-incident, hit.shadingNormal),
                               hit.frontFace ? outside : inside, hit.frontFace ? inside : outside);
    }
  }
  const float reflectedWeight = kr + kt * fresnel,
              transmittedWeight = refracted ? kt * (1.0f - fresnel) : 0.0f;
  if (reflectedWeight > 0.0f && weight * reflectedWeight >= settings.minContribution) {
    const Ray reflected =
        offsetRay(hit, mirrorDirection(incident, hit.shadingNormal), settings.epsilon);
    colour += reflectedWeight * traceRay(reflected, kInfinity, reflected.origin, depth + 1,
                                         weight * reflectedWeight, settings, stats, next, false);
  }
  if (transmittedWeight > 0.0f && weight * transmittedWeight >= settings.minContribution) {
    const Ray transmitted = offsetRay(hit, glm::normalize(*refracted), settings.epsilon);
    colour +=
        transmittedWeight * traceRay(transmitted, kInfinity, transmitted.origin, depth + 1,
                                     weight * transmittedWeight, settings, stats, next, false);
  }
  return colour;
}

glm::vec3 RayTracer::traceRay(const Ray& ray, float tMax, glm::vec3 viewer, uint32_t depth,
                              float weight, const TraceSettings& settings, TraceStats& stats,
                              RayCone cone, bool cameraRay, uint32_t layers) const {
  ++(depth == 0 && layers == 0 ? stats.primaryRays : stats.secondaryRays);
  std::optional<SurfaceHit> hit = intersect(ray, 0.0f, tMax, cameraRay);
  if (!hit) return missColour(scene_, ray.direction);
  return shade(ray, *hit, viewer, depth, weight, settings, stats, cone, cameraRay, layers);
}

// The box-filtered mean of the pixel's n x n stratified samples, each with
// a cone one stratum wide (the box filter averages the strata).
glm::vec3 RayTracer::tracePixel(const CameraRays& camera, uint32_t x, uint32_t y, uint32_t grid,
                                const TraceSettings& settings, TraceStats& stats) const {
  const Ray centre = camera.through(float(x) + 0.5f, float(y) + 0.5f);
  const Ray beside = camera.through(float(x) + 1.5f, float(y) + 0.5f);
  const float nearWidth = glm::length(beside.origin - centre.origin);
  const float farWidth = glm::length(beside.at(1.0f) - centre.at(1.0f));
  const RayCone cone{nearWidth / float(grid),
                     (farWidth - nearWidth) / glm::length(centre.direction) / float(grid)};
  glm::vec3 sum{0.0f};
  for (uint32_t s = 0; s < grid * grid; ++s) {
    float dx = 0.5f, dy = 0.5f;
    if (grid > 1) {
      dx = (float(s % grid) + jitter(x, y, s, 0)) / float(grid);
      dy = (float(s / grid) + jitter(x, y, s, 1)) / float(grid);
    }
    const Ray ray = camera.through(float(x) + dx, float(y) + dy);
    sum += traceRay(ray, 1.0f, camera.viewer(), 0, 1.0f, settings, stats, cone);
  }
  return sum / float(grid * grid);
}

void checkSamplesPerPixel(uint32_t samplesPerPixel, const std::string& name) {
  const uint32_t grid = uint32_t(std::lround(std::sqrt(double(samplesPerPixel))));
  if (samplesPerPixel == 0 || grid * grid != samplesPerPixel || grid > 16)
    throw InputError(name + " " + std::to_string(samplesPerPixel) +
                     ": expected a square number n*n from 1 to 256 (1, 4, 9, 16, ...)");
}

TraceResult RayTracer::render(const TraceSettings& settings) const {
  if (settings.width == 0 || settings.height == 0 || settings.width > 16384 ||
      settings.height > 16384)
    throw InputError("trace size " + std::to_string(settings.width) + "x" +
                     std::to_string(settings.height) + ": expected 1..16384 on each side");
  checkSamplesPerPixel(settings.samplesPerPixel);
  if (!scene_.billboards.empty() && scene_.camera.viewMatrix() != billboardView_)
    throw std::logic_error(
        "RayTracer::render: the camera moved since the tracer turned the "
        "billboards towards it; build a tracer for the new camera");
  const uint32_t grid = uint32_t(std::lround(std::sqrt(double(settings.samplesPerPixel))));
  const CameraRays camera(scene_.camera, settings.width, settings.height);
  TraceResult result{ImageRgba(settings.width, settings.height), {}};
  uint32_t threadCount = settings.threads ? settings.threads : std::thread::hardware_concurrency();
  threadCount = std::clamp<uint32_t>(threadCount, 1, settings.height);
  std::vector<TraceStats> perThread(threadCount);
  std::atomic<uint32_t> nextRow{0}, rowsDone{0};
  // Rows are handed out dynamically, but each pixel depends only on its own
  // coordinates: the image is the same for any thread count and order.
  auto work = [&](TraceStats& stats, bool reports) {
    uint32_t reported = 0;  // hundredths
    for (uint32_t y = nextRow++; y < settings.height; y = nextRow++) {
      if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) return;
      for (uint32_t x = 0; x < settings.width; ++x)
        result.image.set(x, y, glm::vec4(tracePixel(camera, x, y, grid, settings, stats), 1.0f));
      const uint32_t hundredths = uint32_t(100ull * ++rowsDone / settings.height);
      if (reports && settings.progress && hundredths > reported && hundredths < 100)
        settings.progress(float(reported = hundredths) / 100.0f);
    }
  };
  std::vector<std::thread> workers;
  for (uint32_t i = 1; i < threadCount; ++i)
    workers.emplace_back(work, std::ref(perThread[i]), false);
  work(perThread[0], true);
  for (std::thread& worker : workers) worker.join();
  if (settings.progress) settings.progress(1.0f);
  for (const TraceStats& stats : perThread) result.stats += stats;
  return result;
}

}  // namespace shadelab
