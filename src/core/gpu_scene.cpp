#include "core/gpu_scene.h"

#include <algorithm>
#include <cstddef>

#include "core/transform.h"

namespace shadelab {

// The structs in shaders/interface.h must match std140/std430 exactly.
static_assert(sizeof(gpu::GpuLight) == 64);
static_assert(offsetof(gpu::GpuLight, intensity) == 16);
static_assert(offsetof(gpu::GpuLight, type) == 48);
static_assert(offsetof(gpu::FrameData, ambient) == 64);
static_assert(offsetof(gpu::FrameData, lightCount) == 80);
static_assert(offsetof(gpu::FrameData, lights) == 96);
static_assert(sizeof(gpu::FrameData) == 96 + 64 * MAX_LIGHTS);
static_assert(offsetof(gpu::ObjectData, normalMatrix) == 64);
static_assert(sizeof(gpu::ObjectData) == 128);
static_assert(offsetof(gpu::DrawConstants, kd) == 16);
static_assert(offsetof(gpu::DrawConstants, object) == 48);
static_assert(sizeof(gpu::DrawConstants) == 64);  // within the 128 bytes Vulkan guarantees

GpuScene uploadScene(const Context& context, const Scene& scene) {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  std::vector<DrawItem> meshRanges;
  for (const Mesh& mesh : scene.meshes) {
    meshRanges.push_back({uint32_t(indices.size()), uint32_t(mesh.indices.size()),
                          int32_t(vertices.size()), {}});
    vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
  }
  GpuScene gpuScene;
  gpuScene.lightCount = uint32_t(std::min<size_t>(scene.lights.size(), MAX_LIGHTS));
  gpuScene.vertices = uploadBuffer(context, std::as_bytes(std::span(vertices)),
                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  gpuScene.indices = uploadBuffer(context, std::as_bytes(std::span(indices)),
                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  for (uint32_t i = 0; i < scene.objects.size(); ++i) {
    const Object& object = scene.objects[i];
    DrawItem draw = meshRanges[object.mesh];
    draw.constants.ka = glm::vec4(object.material.ka, 0.0f);
    draw.constants.kd = glm::vec4(object.material.kd, 0.0f);
    draw.constants.ks = glm::vec4(object.material.ks, object.material.shininess);
    draw.constants.object = glm::ivec4(int(i), 0, 0, 0);
    gpuScene.draws.push_back(draw);
    gpuScene.triangles += draw.indexCount / 3;
  }
  return gpuScene;
}

gpu::FrameData makeFrameData(const Scene& scene, const glm::mat4& view,
                             const glm::mat4& projection) {
  gpu::FrameData frame{};
  frame.projection = projection;
  frame.ambient = glm::vec4(scene.ambient, 0.0f);
  size_t count = std::min<size_t>(scene.lights.size(), MAX_LIGHTS);
  frame.lightCount = glm::ivec4(int(count), 0, 0, 0);
  for (size_t i = 0; i < count; ++i) {
    const Light& light = scene.lights[i];
    gpu::GpuLight& out = frame.lights[i];
    if (light.type == LightType::Point) {
      out.position = view * glm::vec4(light.position, 1.0f);
      out.type.x = LIGHT_POINT;
    } else {
      // Directions transform without translation; the shader wants "towards the light".
      out.position = glm::vec4(glm::mat3(view) * -light.direction, 0.0f);
      out.type.x = LIGHT_DIRECTIONAL;
    }
    out.intensity = glm::vec4(light.intensity, 0.0f);
    out.attenuation = glm::vec4(light.attenuation, 0.0f);
  }
  return frame;
}

std::vector<gpu::ObjectData> makeObjectData(const Scene& scene, const glm::mat4& view,
                                           NormalTransform normals) {
  std::vector<gpu::ObjectData> objects;
  objects.reserve(scene.objects.size());
  for (const Object& object : scene.objects) {
    gpu::ObjectData data{};
    data.modelView = view * object.transform;
    data.normalMatrix = normals == NormalTransform::InverseTranspose
                            ? glm::mat4(normalMatrix(data.modelView))
                            : glm::mat4(glm::mat3(data.modelView));
    objects.push_back(data);
  }
  return objects;
}

}  // namespace shadelab
