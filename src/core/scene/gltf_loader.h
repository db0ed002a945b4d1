#pragma once
// glTF 2.0 (.gltf with external or embedded buffers, .glb) into the scene
// model, through tinygltf. What maps to what (materials, lights, cameras,
// samplers) is listed in README.md ("glTF scenes"); every problem in a file
// throws InputError "<file>: <where>: <what>".
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace shadelab {

// What a glTF file brings besides its objects, in the world space of the
// scene it was added to.
struct GltfImport {
  std::vector<Light> lights;     // KHR_lights_punctual, scene order
  std::optional<Camera> camera;  // the first camera node of the scene
};

// The most objects (one per mesh primitive per node that places it) one
// file may add; more is refused with the file named.
inline constexpr size_t kMaxGltfObjects = 262'144;

// Appends the file's meshes, materials and textures to `scene`, each object
// under `parent` (the matrix stack continues into the glTF node hierarchy).
GltfImport appendGltf(Scene& scene, const std::filesystem::path& path,
                      const glm::mat4& parent = glm::mat4(1.0f));

// A glTF file as a whole scene: its camera and lights, or when it has none a
// camera framing its bounding box and a default key light.
Scene loadGltfScene(const std::filesystem::path& path);

// The same from bytes in memory (glTF JSON or GLB, told apart by the "glTF"
// magic); external buffers and images are refused, not read. For the fuzzer.
Scene parseGltfScene(std::span<const uint8_t> bytes, const std::string& sourceName);

// The camera and light loadGltfScene gives a file that has none.
Camera frameBounds(const Bounds& worldBounds);
Light defaultKeyLight(const Camera& camera);
Bounds sceneBounds(const Scene& scene);  // of every object, world space

}  // namespace shadelab
