// glTF accessors and primitives to meshes. Every accessor is checked against
// its buffer view and buffer before a byte is read, and every index against
// the vertex count, so a malformed file is an InputError, never a crash.
#include <meshoptimizer.h>

#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <string>

#include "core/base/errors.h"
#include "core/scene/gltf_detail.h"

namespace shadelab::gltf {
namespace {

int componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

// An accessor's elements as bytes: base pointer, stride and count, checked.
struct ElementView {
  const uint8_t* base = nullptr;
  size_t stride = 0;
  size_t count = 0;
  int componentType = 0;
  bool normalized = false;
};

class PrimitiveReader {
 public:
  PrimitiveReader(const tinygltf::Model& model, const std::string& source, std::string where)
      : model_(model), source_(source), where_(std::move(where)) {}

  [[noreturn]] void fail(const std::string& what) const { gltf::fail(source_, where_, what); }

  ElementView view(int accessorIndex, const std::string& role, int type) const {
    if (accessorIndex < 0 || size_t(accessorIndex) >= model_.accessors.size())
      fail(role + " refers to accessor " + std::to_string(accessorIndex) + ", but the file has " +
           std::to_string(model_.accessors.size()));
    const tinygltf::Accessor& accessor = model_.accessors[size_t(accessorIndex)];
    std::string name = role + " (accessors[" + std::to_string(accessorIndex) + "])";
    if (accessor.sparse.isSparse) fail(name + " is sparse; sparse accessors are not supported");
    if (componentCount(accessor.type) != componentCount(type))
      fail(name + " has the wrong type for " + role);
    int size = componentSize(accessor.componentType);
    if (size == 0)
      fail(name + " has an invalid componentType " + std::to_string(accessor.componentType));
    if (accessor.bufferView < 0 || size_t(accessor.bufferView) >= model_.bufferViews.size())
      fail(name + " has no valid bufferView (" + std::to_string(accessor.bufferView) + ")");
    const tinygltf::BufferView& bufferView = model_.bufferViews[size_t(accessor.bufferView)];
    if (bufferView.buffer < 0 || size_t(bufferView.buffer) >= model_.buffers.size())
      fail(name + ": its bufferView refers to a missing buffer " +
           std::to_string(bufferView.buffer));
    const tinygltf::Buffer& buffer = model_.buffers[size_t(bufferView.buffer)];
    uint64_t elementSize = uint64_t(size) * uint64_t(componentCount(type));
    uint64_t stride = bufferView.byteStride ? uint64_t(bufferView.byteStride) : elementSize;
    if (stride < elementSize)
      fail(name + ": byteStride " + std::to_string(stride) + " is smaller than an element (" +
           std::to_string(elementSize) + " bytes)");
    // Offsets, counts and lengths are the file's: every sum and product is
    // checked for overflow before it is compared with the buffer's size.
    uint64_t viewEnd = 0;
    if (__builtin_add_overflow(uint64_t(bufferView.byteOffset), uint64_t(bufferView.byteLength),
                               &viewEnd) ||
        viewEnd > buffer.data.size())
      fail(name + ": bufferViews[" + std::to_string(accessor.bufferView) + "] (byteOffset " +
           std::to_string(bufferView.byteOffset) + ", byteLength " +
           std::to_string(bufferView.byteLength) + ") runs past the end of its buffer (" +
           std::to_string(buffer.data.size()) + " bytes)");
    uint64_t end = 0;  // one past the accessor's last byte, from the view's start
    bool overflow = false;
    if (accessor.count > 0) {
      uint64_t span = 0;
      overflow = __builtin_mul_overflow(stride, uint64_t(accessor.count) - 1, &span) ||
                 __builtin_add_overflow(span, elementSize, &span) ||
                 __builtin_add_overflow(span, uint64_t(accessor.byteOffset), &end);
    }
    if (overflow || end > bufferView.byteLength)
      fail(name + ": " + std::to_string(accessor.count) + " elements from byte " +
           std::to_string(accessor.byteOffset) + " need " +
           (overflow ? std::string("more than 2^64") : std::to_string(end)) +
           " bytes, past the end of its bufferView (" + std::to_string(bufferView.byteLength) +
           " bytes)");
    return ElementView{buffer.data.data() + bufferView.byteOffset + accessor.byteOffset,
                       size_t(stride), accessor.count, accessor.componentType, accessor.normalized};
  }

  // Floats, or normalised integers converted as the glTF spec says
  // (unsigned: c / max; signed: max(c / max, -1)).
  std::vector<float> floats(int accessorIndex, const std::string& role, int type,
                            bool allowNormalized) const {
    ElementView elements = view(accessorIndex, role, type);
    bool isFloat = elements.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (!isFloat && !(allowNormalized && elements.normalized &&
                      elements.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT &&
                      elements.componentType != TINYGLTF_COMPONENT_TYPE_INT))
      fail(role + " must be FLOAT" +
           std::string(allowNormalized ? " or normalized UNSIGNED_BYTE/UNSIGNED_SHORT" : "") +
           " (componentType " + std::to_string(elements.componentType) + ")");
    size_t components = size_t(componentCount(type));
    std::vector<float> values(elements.count * components);
    for (size_t i = 0; i < elements.count; ++i)
      for (size_t c = 0; c < components; ++c) {
        const uint8_t* at = elements.base + i * elements.stride;
        values[i * components + c] = component(at, c, elements.componentType);
      }
    for (float value : values)
      if (!std::isfinite(value)) fail(role + " holds a non-finite value (NaN or infinity)");
    return values;
  }

  std::vector<uint32_t> indices(int accessorIndex, size_t vertexCount) const {
    ElementView elements = view(accessorIndex, "indices", TINYGLTF_TYPE_SCALAR);
    std::vector<uint32_t> values(elements.count);
    for (size_t i = 0; i < elements.count; ++i) {
      const uint8_t* at = elements.base + i * elements.stride;
      switch (elements.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          values[i] = *at;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
          values[i] = load<uint16_t>(at);
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
          values[i] = load<uint32_t>(at);
          break;
        default:
          fail("indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT (componentType " +
               std::to_string(elements.componentType) + ")");
      }
      if (values[i] >= vertexCount)
        fail("index " + std::to_string(values[i]) + " at position " + std::to_string(i) +
             " is out of range: the primitive has " + std::to_string(vertexCount) + " vertices");
    }
    return values;
  }

 private:
  template <typename T>
  static T load(const uint8_t* at) {
    T value;
    std::memcpy(&value, at, sizeof(T));  // glTF data need not be aligned for T
    return value;
  }

  static float component(const uint8_t* element, size_t c, int componentType) {
    switch (componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load<float>(element + 4 * c);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return float(element[c]) / 255.0f;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return float(load<uint16_t>(element + 2 * c)) / 65535.0f;
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return std::max(float(int8_t(element[c])) / 127.0f, -1.0f);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return std::max(float(load<int16_t>(element + 2 * c)) / 32767.0f, -1.0f);
      default:
        return 0.0f;
    }
  }

  const tinygltf::Model& model_;
  const std::string& source_;
  std::string where_;
};

// Triangle lists from the primitive's topology (glTF 2.0 spec, 3.7.2.1):
// strip triangle i is (v_i, v_{i+1+i%2}, v_{i+2-i%2}), keeping every
// triangle counter-clockwise; fan triangle i is (v_{i+1}, v_{i+2}, v_0).
std::vector<uint32_t> triangleList(const std::vector<uint32_t>& order, int mode) {
  std::vector<uint32_t> triangles;
  size_t n = order.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    triangles.assign(order.begin(), order.begin() + long(n - n % 3));
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < n; ++i)
      triangles.insert(triangles.end(), {order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 0; i + 2 < n; ++i)
      triangles.insert(triangles.end(), {order[i + 1], order[i + 2], order[0]});
  }
  return triangles;
}

int attribute(const tinygltf::Primitive& primitive, const char* name) {
  auto found = primitive.attributes.find(name);
  return found == primitive.attributes.end() ? -1 : found->second;
}

// Vertex cache order first, then vertices in first-use order (meshoptimizer).
void optimiseForDevice(Mesh& mesh) {
  meshopt_optimizeVertexCache(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(),
                              mesh.vertices.size());
  size_t used =
      meshopt_optimizeVertexFetch(mesh.vertices.data(), mesh.indices.data(), mesh.indices.size(),
                                  mesh.vertices.data(), mesh.vertices.size(), sizeof(Vertex));
  mesh.vertices.resize(used);
}

// Non-indexed input repeats shared vertices; merging identical ones gives
// the vertex cache something to reuse.
void mergeIdenticalVertices(Mesh& mesh) {
  std::vector<uint32_t> remap(mesh.vertices.size());
  size_t unique =
      meshopt_generateVertexRemap(remap.data(), mesh.indices.data(), mesh.indices.size(),
                                  mesh.vertices.data(), mesh.vertices.size(), sizeof(Vertex));
  std::vector<Vertex> vertices(unique);
  meshopt_remapVertexBuffer(vertices.data(), mesh.vertices.data(), mesh.vertices.size(),
                            sizeof(Vertex), remap.data());
  meshopt_remapIndexBuffer(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(),
                           remap.data());
  mesh.vertices = std::move(vertices);
}

}  // namespace

void fail(const std::string& source, const std::string& where, const std::string& what) {
  throw InputError(source + ": " + (where.empty() ? "" : where + ": ") + what);
}

std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string describeMesh(const tinygltf::Model& model, int mesh) {
  std::string text = "meshes[" + std::to_string(mesh) + "]";
  const std::string& name = model.meshes[size_t(mesh)].name;
  return name.empty() ? text : text + " '" + name + "'";
}

Mesh primitiveMesh(const tinygltf::Model& model, const std::string& source, int meshIndex,
                   int primitiveIndex, bool needTangents, int texCoordSet) {
  const tinygltf::Primitive& primitive =
      model.meshes[size_t(meshIndex)].primitives[size_t(primitiveIndex)];
  PrimitiveReader reader(
      model, source,
      describeMesh(model, meshIndex) + " primitives[" + std::to_string(primitiveIndex) + "]");
  int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
  if (mode > TINYGLTF_MODE_TRIANGLE_FAN) reader.fail("unknown mode " + std::to_string(mode));
  // Attributes shadelab does not draw (JOINTS_n, WEIGHTS_n, COLOR_n, morph
  // targets) are still the file's: one naming a missing accessor is broken.
  auto checkAccessors = [&](const std::map<std::string, int>& attributes,
                            const std::string& where) {
    for (const auto& [name, index] : attributes)
      if (index < 0 || size_t(index) >= model.accessors.size())
        reader.fail(where + name + " refers to accessor " + std::to_string(index) +
                    ", but the file has " + std::to_string(model.accessors.size()));
  };
  checkAccessors(primitive.attributes, "");
  for (size_t t = 0; t < primitive.targets.size(); ++t)
    checkAccessors(primitive.targets[t], "targets[" + std::to_string(t) + "].");
  if (mode < TINYGLTF_MODE_TRIANGLES) return Mesh{};  // points and lines are not drawn

  int positionAccessor = attribute(primitive, "POSITION");
  if (positionAccessor < 0) reader.fail("no POSITION attribute");
  std::vector<float> positions =
      reader.floats(positionAccessor, "POSITION", TINYGLTF_TYPE_VEC3, false);
  size_t count = positions.size() / 3;
  Mesh mesh;
  mesh.vertices.resize(count,
                       Vertex{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec2(0.0f), glm::vec4(0.0f)});
  for (size_t i = 0; i < count; ++i)
    mesh.vertices[i].position =
        glm::vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
  auto fill = [&](const char* name, int type, bool normalized, auto&& store) {
    int accessor = attribute(primitive, name);
    if (accessor < 0) return false;
    std::vector<float> values = reader.floats(accessor, name, type, normalized);
    size_t components = size_t(componentCount(type));
    if (values.size() / components != count)
      reader.fail(std::string(name) + " has " + std::to_string(values.size() / components) +
                  " elements but POSITION has " + std::to_string(count));
    for (size_t i = 0; i < count; ++i) store(mesh.vertices[i], &values[i * components]);
    return true;
  };
  bool hasNormals = fill("NORMAL", TINYGLTF_TYPE_VEC3, false,
                         [](Vertex& v, const float* f) { v.normal = glm::vec3(f[0], f[1], f[2]); });
  // glTF's v runs down the image from its first row; ours runs up (the
  // shaders sample t = 1 - v), so v flips. Tangents need no change: glTF's
  // bitangent w cross(N, T) already points up the image, as ours does.
  std::string texCoords = "TEXCOORD_" + std::to_string(texCoordSet);
  fill(texCoords.c_str(), TINYGLTF_TYPE_VEC2, true,
       [](Vertex& v, const float* f) { v.uv = glm::vec2(f[0], 1.0f - f[1]); });
  bool hasTangents = fill("TANGENT", TINYGLTF_TYPE_VEC4, false, [](Vertex& v, const float* f) {
    v.tangent = glm::vec4(f[0], f[1], f[2], f[3] < 0.0f ? -1.0f : 1.0f);
  });

  std::vector<uint32_t> order;
  if (primitive.indices >= 0) {
    order = reader.indices(primitive.indices, count);
  } else {
    order.resize(count);
    for (size_t i = 0; i < count; ++i) order[i] = uint32_t(i);
  }
  mesh.indices = triangleList(order, mode);
  if (mesh.indices.empty())
    reader.fail("no triangles (" + std::to_string(order.size()) + " vertices in mode " +
                std::to_string(mode) + ")");
  if (primitive.indices < 0) mergeIdenticalVertices(mesh);
  // The spec asks for flat normals when a primitive has none.
  if (!hasNormals) computeCreaseNormals(mesh, 0.0f);
  if (needTangents && !hasTangents) computeTangents(mesh);
  optimiseForDevice(mesh);
  return mesh;
}

}  // namespace shadelab::gltf
