#pragma once
// A scene's geometry on the device (one vertex and one index buffer for all
// meshes) and the per-frame data the shaders read, built from the scene and
// the camera.
#include <vector>

#include "core/resources.h"
#include "core/scene.h"
#include "interface.h"

namespace shadelab {

// How normals go to eye space. Only the inverse transpose keeps them
// perpendicular to the surface under non-uniform scale; the plain
// model-view is the classic mistake, kept so tests can show what it breaks.
enum class NormalTransform { InverseTranspose, ModelView };

struct DrawItem {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  gpu::DrawConstants constants{};  // material and object index, pushed per draw
};

struct GpuScene {
  Buffer vertices;
  Buffer indices;
  std::vector<DrawItem> draws;
  uint64_t triangles = 0;
  uint32_t lightCount = 0;  // lights the shaders loop over (at most MAX_LIGHTS)
};

GpuScene uploadScene(const Context& context, const Scene& scene);

// Lights move to eye space, so the shaders light with V = -position.
gpu::FrameData makeFrameData(const Scene& scene, const glm::mat4& view, const glm::mat4& projection);
// Model-view and its normal matrix (inverse transpose) per object.
// Materials travel with the draws (DrawItem::constants).
std::vector<gpu::ObjectData> makeObjectData(
    const Scene& scene, const glm::mat4& view,
    NormalTransform normals = NormalTransform::InverseTranspose);

}  // namespace shadelab
