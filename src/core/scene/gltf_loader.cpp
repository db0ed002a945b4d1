#include "core/scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/json_nesting.h"
#include "core/scene/encoded_image.h"
#include "core/scene/frustum.h"
#include "core/scene/gltf_detail.h"
#include "core/scene/texture.h"
#include "core/scene/transform.h"
#include "interface.h"

namespace shadelab {
namespace {

using gltf::fail;

// Extensions whose absence changes nothing we draw, or that we implement.
const std::set<std::string> kSupportedExtensions = {
    "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_texture_transform"};
constexpr int kMaxDepth = 1024;  // node nesting; deeper is an attack on the stack, not a model

std::vector<uint8_t> readFile(const std::filesystem::path& path) {
  std::string name = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw InputError("glTF file '" + name + "' does not exist");
  if (std::filesystem::is_directory(path, error))
    throw InputError("glTF file '" + name + "' is a directory");
  std::string text = readInputFile(path, "glTF file", kMaxBinaryInputBytes);
  return std::vector<uint8_t>(text.begin(), text.end());
}

// External files (buffers[].uri, images[].uri) of a model read from disk: a
// URI may not be absolute or climb out of the model's folder with "..", so a
// downloaded model cannot read /etc/passwd or ~/.ssh as geometry. Links inside
// the folder are followed: they were put there by the user, not by the file.
// Only regular files below kMaxBinaryInputBytes are read.
struct ModelFolder {
  std::filesystem::path folder;  // absolute, normalised
};
bool fileExistsInFolder(const std::string& path, void*) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}
bool readFileInFolder(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                      void* userData) {
  const auto* model = static_cast<const ModelFolder*>(userData);
  std::filesystem::path file = std::filesystem::absolute(path).lexically_normal();
  std::filesystem::path relative = file.lexically_relative(model->folder);
  if (relative.empty() || *relative.begin() == "..") {
    if (error)
      *error += "outside the model's folder '" + model->folder.string() +
                "' (external files must lie under it)";
    return false;
  }
  try {
    std::string bytes = readInputFile(file, "external file", kMaxBinaryInputBytes);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& refused) {
    if (error) *error += refused.what();
    return false;
  }
}

// In-memory loads (the fuzzer) must not touch the file system.
bool noFileExists(const std::string&, void*) {
  return false;
}
std::string keepPath(const std::string& path, void*) {
  return path;
}
bool refuseRead(std::vector<unsigned char>*, std::string* error, const std::string& path, void*) {
  if (error) *error += "external file '" + path + "' not read (loading from memory)";
  return false;
}
bool refuseWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

// Every image tinygltf decodes (data URIs, bufferViews, external files) comes
// here first, with `userData` the model being filled (its buffers and
// bufferViews are read before its images).
// - An image in a bufferView: tinygltf 2.7 hands over &buffer.data[byteOffset]
//   and byteLength unchecked, so a view past its buffer (or into a buffer
//   that failed to load) would be read out of bounds; the view must lie
//   inside the buffer's data.
// - Its header must declare a PNG or JPEG (the formats glTF 2.0 allows) of at
//   most kMaxTextureSide texels a side, as for texture files, before a byte
//   is decoded.
// The model being read, and the scene's texels so far (checkSceneTexels):
// the scene's textures before the file, then each image of it as declared.
struct ImageLoad {
  tinygltf::Model* model = nullptr;
  uint64_t texels = 0;
};

bool loadImageChecked(tinygltf::Image* image, const int index, std::string* error,
                      std::string* warning, int requiredWidth, int requiredHeight,
                      const unsigned char* bytes, int size, void* userData) {
  std::string name = "images[" + std::to_string(index) + "]";
  auto refuse = [&](const std::string& what) {
    if (error) *error += name + ": " + what;
    return false;
  };
  auto* load = static_cast<ImageLoad*>(userData);
  const tinygltf::Model* model = load->model;
  if (image->bufferView >= 0) {
    // tinygltf checked both indices before calling.
    const tinygltf::BufferView& view = model->bufferViews.at(size_t(image->bufferView));
    const tinygltf::Buffer& buffer = model->buffers.at(size_t(view.buffer));
    size_t end = 0;
    if (__builtin_add_overflow(view.byteOffset, view.byteLength, &end) ||
        end > buffer.data.size() || view.byteLength > size_t(std::numeric_limits<int>::max()))
      return refuse("bufferView " + std::to_string(image->bufferView) + " (bytes " +
                    std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                    ") lies outside its buffer's " + std::to_string(buffer.data.size()) + " bytes");
    bytes = buffer.data.data() + view.byteOffset;
    size = int(view.byteLength);
  }
  std::optional<EncodedImageSize> declared = encodedImageSize(bytes, size_t(std::max(size, 0)));
  if (!declared) return refuse("not a PNG or JPEG image (glTF 2.0 allows only these)");
  if (declared->width > kMaxTextureSide || declared->height > kMaxTextureSide)
    return refuse(std::to_string(declared->width) + "x" + std::to_string(declared->height) +
                  " texels, more than the " + std::to_string(kMaxTextureSide) +
                  " allowed on a side");
  try {
    checkSceneTexels("image", declared->width, declared->height, load->texels);
  } catch (const InputError& tooMany) {
    return refuse(std::string(tooMany.what()).substr(std::string("image: ").size()));
  }
  load->texels += uint64_t(declared->width) * uint64_t(declared->height);
  // nullptr: tinygltf's default options (4 channels).
  return tinygltf::LoadImageData(image, index, error, warning, requiredWidth, requiredHeight, bytes,
                                 size, nullptr);
}

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ';');
  return text;
}

// tinygltf says only "Invalid glTF binary" for a short file and accepts any
// version: say what is wrong. Also limits the JSON chunk's nesting.
// The JSON chunk of a GLB whose header checkGlbHeader accepted.
std::string_view glbJson(std::span<const uint8_t> bytes) {
  if (bytes.size() < 20) return {};
  uint32_t chunkLength = 0;
  std::memcpy(&chunkLength, bytes.data() + 12, 4);
  return std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20,
                          std::min<size_t>(chunkLength, bytes.size() - 20));
}

void checkGlbHeader(std::span<const uint8_t> bytes, const std::string& source) {
  if (bytes.size() < 12)
    throw InputError(source + ": invalid GLB: truncated, " + std::to_string(bytes.size()) +
                     " bytes, less than the 12-byte header");
  // Little-endian, as on every host we build for.
  uint32_t version = 0, length = 0;
  std::memcpy(&version, bytes.data() + 4, 4);
  std::memcpy(&length, bytes.data() + 8, 4);
  if (version != 2)
    throw InputError(source + ": invalid GLB: version " + std::to_string(version) +
                     " in the header, expected 2 (glTF 2.0)");
  if (length > bytes.size())
    throw InputError(source + ": invalid GLB: truncated, the header gives " +
                     std::to_string(length) + " bytes but the file has " +
                     std::to_string(bytes.size()));
  uint32_t chunkLength = 0;
  if (bytes.size() >= 20) {
    std::memcpy(&chunkLength, bytes.data() + 12, 4);
    size_t available = bytes.size() - 20;
    checkJsonNesting(std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20,
                                      std::min<size_t>(chunkLength, available)),
                     source);
  }
}

tinygltf::Model parseModel(std::span<const uint8_t> bytes, const std::string& source,
                           const std::string& baseDir, bool allowFiles, uint64_t texelsBefore) {
  tinygltf::TinyGLTF loader;
  ModelFolder folder{std::filesystem::absolute(baseDir.empty() ? "." : baseDir).lexically_normal()};
  if (allowFiles)
    loader.SetFsCallbacks(
        {&fileExistsInFolder, &keepPath, &readFileInFolder, &refuseWrite, &folder});
  else
    loader.SetFsCallbacks({&noFileExists, &keepPath, &refuseRead, &refuseWrite, nullptr});
  tinygltf::Model model;
  ImageLoad imageLoad{&model, texelsBefore};
  loader.SetImageLoader(&loadImageChecked, &imageLoad);
  std::string error, warning;
  bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (bytes.size() > std::numeric_limits<unsigned int>::max())
    throw InputError(source + ": file too large");
  if (binary)
    checkGlbHeader(bytes, source);
  else
    checkJsonNesting(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                     source);
  bool ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(),
                                                 unsigned(bytes.size()), baseDir)
                   : loader.LoadASCIIFromString(&model, &error, &warning,
                                                reinterpret_cast<const char*>(bytes.data()),
                                                unsigned(bytes.size()), baseDir);
  // tinygltf also reports some errors and carries on with the default
  // (a baseColorFactor of 5 numbers leaves it white): those are errors too.
  if (!ok || !error.empty())
    throw InputError(source + ": invalid " + (binary ? "GLB" : "glTF") + ": " +
                     trimmed(error.empty() ? warning : error));
  gltf::checkAlphaCutoffs(
      binary ? glbJson(bytes)
             : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
      source);
  // glTF 2.x: a later major version may mean anything (the spec: a loader
  // must not load an asset whose major version it does not know).
  if (model.asset.version.rfind("2.", 0) != 0)
    fail(source, "asset.version",
         "\"" + model.asset.version.substr(0, 32) + "\"; expected a glTF 2.x version (\"2.0\")");
  for (const std::string& extension : model.extensionsRequired)
    if (!kSupportedExtensions.count(extension))
      throw InputError(source + ": extensionsRequired: \"" + extension +
                       "\" is not supported (shadelab supports KHR_lights_punctual, "
                       "KHR_materials_emissive_strength and KHR_texture_transform)");
  // tinygltf only warns when an external buffer is missing; nothing can be
  // drawn from it, so it is an error here.
  for (size_t i = 0; i < model.buffers.size(); ++i)
    if (model.buffers[i].data.empty() && !model.buffers[i].uri.empty())
      fail(source, "buffers[" + std::to_string(i) + "]",
           "'" + model.buffers[i].uri.substr(0, 64) + "' could not be loaded: " + trimmed(warning));
  return model;
}

glm::mat4 localMatrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(node.matrix[size_t(i)]);
    return m;  // glTF stores column-major, as GLM does
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3)
    m = translation(glm::vec3(float(node.translation[0]), float(node.translation[1]),
                              float(node.translation[2])));
  if (node.rotation.size() == 4) {
    // glTF quaternions are (x, y, z, w); GLM's constructor takes w first.
    glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
                float(node.rotation[2]));
    if (glm::length(q) > 0.0f) m = m * glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3)
    m = m * scaling(glm::vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2])));
  return m;  // M = T R S
}

class NodeWalker {
 public:
  NodeWalker(const tinygltf::Model& model, const std::string& source, Scene& scene)
      : model_(model), source_(source), scene_(scene), materials_(model, source, scene) {}

  GltfImport walk(const glm::mat4& parent) {
    GltfImport result;
    result_ = &result;
    size_t before = scene_.objects.size();
    for (int root : rootNodes()) visit(root, parent, 0);
    if (scene_.objects.size() == before) fail(source_, "", "the scene has no triangles to draw");
    return result;
  }

 private:
  std::vector<int> rootNodes() const {
    if (!model_.scenes.empty()) {
      int index = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (size_t(index) >= model_.scenes.size())
        fail(source_, "scene",
             "refers to scene " + std::to_string(index) + ", which does not exist");
      return model_.scenes[size_t(index)].nodes;
    }
    // No scenes: every node that is nobody's child is a root.
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
      for (int child : node.children)
        if (child >= 0 && size_t(child) < isChild.size()) isChild[size_t(child)] = true;
    std::vector<int> roots;
    for (size_t i = 0; i < model_.nodes.size(); ++i)
      if (!isChild[i]) roots.push_back(int(i));
    return roots;
  }

  // The matrix stack: a node's world matrix is its parent's times its own.
  void visit(int index, const glm::mat4& parent, int depth) {
    std::string where = "nodes[" + std::to_string(index) + "]";
    if (index < 0 || size_t(index) >= model_.nodes.size())
      fail(source_, where,
           "no such node (the file has " + std::to_string(model_.nodes.size()) + ")");
    // A node has at most one parent, so meeting one twice means a cycle or a
    // shared child, which glTF forbids.
    if (!visited_.insert(index).second)
      fail(source_, where, "is reached twice (the node hierarchy must be a tree)");
    if (depth > kMaxDepth)
      fail(source_, where, "nested more than " + std::to_string(kMaxDepth) + " levels deep");
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    // A wrong length would otherwise be ignored: the node drawn untransformed.
    for (auto [field, size, expected] :
         {std::tuple{"matrix", node.matrix.size(), size_t(16)},
          std::tuple{"translation", node.translation.size(), size_t(3)},
          std::tuple{"rotation", node.rotation.size(), size_t(4)},
          std::tuple{"scale", node.scale.size(), size_t(3)}})
      if (size != 0 && size != expected)
        fail(source_, where + "." + field,
             std::to_string(size) + " numbers; expected " + std::to_string(expected));
    if (node.rotation.size() == 4 &&
        !(glm::length(glm::dvec4(node.rotation[0], node.rotation[1], node.rotation[2],
                                 node.rotation[3])) > 1e-6))
      fail(source_, where + ".rotation", "has no length; expected a unit quaternion (x, y, z, w)");
    glm::mat4 world = parent * localMatrix(node);
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 4; ++row)
        if (!std::isfinite(world[column][row]))
          fail(source_, where,
               "its transform (matrix or translation/rotation/scale) is not finite");
    // A node scaled to nothing (a common way to hide one) draws nothing, and
    // its normals would have no inverse transpose.
    bool collapsed = glm::determinant(glm::mat3(world)) == 0.0f;
    if (node.mesh >= 0 && !collapsed) addMesh(node.mesh, world, where);
    if (node.camera >= 0 && !result_->camera) result_->camera = camera(node.camera, world, where);
    auto light = node.extensions.find("KHR_lights_punctual");
    if (light != node.extensions.end() && light->second.Has("light")) {
      // A JSON number of any size: converting 1e308 to int is undefined
      // (found by the fuzzer), so it is checked as a double first.
      const tinygltf::Value& value = light->second.Get("light");
      double index = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
      if (!(index >= 0.0 && index < double(model_.lights.size())) || index != std::floor(index))
        fail(source_, where + ": KHR_lights_punctual",
             "'light' must be the index of one of the file's " +
                 std::to_string(model_.lights.size()) + " lights");
      addLight(int(index), world, where);
    }
    for (int child : node.children) visit(child, world, depth + 1);
  }

  void addMesh(int meshIndex, const glm::mat4& world, const std::string& where) {
    if (size_t(meshIndex) >= model_.meshes.size())
      fail(source_, where,
           "refers to mesh " + std::to_string(meshIndex) + ", which does not exist");
    const tinygltf::Mesh& mesh = model_.meshes[size_t(meshIndex)];
    // A mirroring transform turns counter-clockwise triangles clockwise; the
    // spec asks for the winding to be flipped so back-face culling still works.
    bool mirrored = mirrors(world);
    size_t before = scene_.objects.size();
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      int materialIndex = mesh.primitives[p].material;
      const Material& material = materials_.material(materialIndex);
      int texCoordSet = materials_.texCoordSet(materialIndex);
      // A texture on a uv set the primitive lacks would be sampled at (0, 0)
      // everywhere: one flat colour, silently.
      std::string uvSet = "TEXCOORD_" + std::to_string(texCoordSet);
      if ((material.diffuseMap.present() || material.normalMap.present()) &&
          !mesh.primitives[p].attributes.count(uvSet))
        fail(source_,
             gltf::describeMesh(model_, meshIndex) + ".primitives[" + std::to_string(p) + "]",
             "its material's textures read " + uvSet + ", which it does not have");
      auto key = std::make_tuple(meshIndex, int(p), mirrored, texCoordSet);
      auto found = meshes_.find(key);
      if (found == meshes_.end()) {
        Mesh built = gltf::primitiveMesh(model_, source_, meshIndex, int(p),
                                         materials_.needsTangents(materialIndex), texCoordSet);
        if (built.indices.empty()) continue;  // points or lines
        if (mirrored) reverseWinding(built);
        found = meshes_.emplace(key, scene_.addMesh(std::move(built))).first;
      }
      std::string name = mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : mesh.name;
      if (mesh.primitives.size() > 1) name += " #" + std::to_string(p);
      // Nodes share meshes, so a small file can place millions of objects
      // (1,000 nodes of a mesh of 20,000 primitives): refused here, before
      // they take gigabytes, not after.
      if (++placed_ > kMaxGltfObjects)
        fail(source_, where,
             "the file's nodes place more than " + std::to_string(kMaxGltfObjects) +
                 " objects (one per mesh primitive per node); expected at most that many");
      scene_.objects.push_back({name, found->second, world, material});
    }
    if (scene_.objects.size() == before)
      fail(source_, gltf::describeMesh(model_, meshIndex), "has no triangles to draw");
    // A finite matrix can still carry finite vertices past the float range
    // (a scale of 1e38): the box's corners, taken to the world, show it.
    for (size_t o = before; o < scene_.objects.size(); ++o) {
      uint32_t meshOf = scene_.objects[o].mesh;
      auto boxFound = meshBounds_.find(meshOf);
      if (boxFound == meshBounds_.end())
        boxFound = meshBounds_.emplace(meshOf, computeBounds(scene_.meshes[meshOf])).first;
      const Bounds& box = boxFound->second;
      for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 local(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                        corner & 4 ? box.max.z : box.min.z);
        glm::vec4 placed = world * glm::vec4(local, 1.0f);
        if (!std::isfinite(placed.x) || !std::isfinite(placed.y) || !std::isfinite(placed.z))
          fail(source_, where,
               "its transform takes " + gltf::describeMesh(model_, meshIndex) +
                   " beyond the float range (expected a scene whose coordinates stay below "
                   "about 1e38)");
      }
    }
  }

  Camera camera(int index, const glm::mat4& world, const std::string& where) const {
    if (size_t(index) >= model_.cameras.size())
      fail(source_, where, "refers to camera " + std::to_string(index) + ", which does not exist");
    const tinygltf::Camera& source = model_.cameras[size_t(index)];
    std::string cameraWhere = "cameras[" + std::to_string(index) + "]";
    Camera camera;
    // glTF cameras look down their local -z with +y up.
    camera.eye = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    camera.at = camera.eye + glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    camera.up = glm::vec3(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    if (source.type == "orthographic") {
      const tinygltf::OrthographicCamera& ortho = source.orthographic;
      camera.projection = Projection::Orthographic;
      camera.left = -float(std::abs(ortho.xmag));
      camera.right = float(std::abs(ortho.xmag));
      camera.bottom = -float(std::abs(ortho.ymag));
      camera.top = float(std::abs(ortho.ymag));
      camera.near = float(ortho.znear);
      camera.far = float(ortho.zfar);
    } else {
      const tinygltf::PerspectiveCamera& perspective = source.perspective;
      camera.fovyDegrees = glm::degrees(float(perspective.yfov));
      camera.near = float(perspective.znear);
      // No zfar means an infinite projection; a finite far plane 10^4 times
      // the near plane keeps the depth buffer's precision usable.
      camera.far = perspective.zfar > 0.0 ? float(perspective.zfar) : camera.near * 1e4f;
      if (!(camera.fovyDegrees > 0.0f && camera.fovyDegrees < 180.0f))
        fail(source_, cameraWhere,
             "yfov " + std::to_string(perspective.yfov) + " is not between 0 and pi radians");
    }
    bool degenerate = glm::length(glm::cross(camera.at - camera.eye, camera.up)) < 1e-6f;
    if (!(camera.near >= 0.0f && camera.far > camera.near) || camera.left == camera.right ||
        camera.bottom == camera.top || degenerate)
      fail(source_, cameraWhere, "degenerate camera (znear/zfar, xmag/ymag or node transform)");
    if (camera.projection == Projection::Perspective && camera.near == 0.0f)
      fail(source_, cameraWhere, "znear is 0");
    // The checks every camera gets (a field of view or window too narrow to
    // draw), named here: later they would blame the command line's options.
    if (std::optional<CameraProblem> problem = findCameraProblem(camera))
      fail(source_, cameraWhere, problem->problem + ", expected " + problem->expected);
    return camera;
  }

  // KHR_lights_punctual, intensities in the extension's units (candela for
  // point and spot, lux for directional) taken as Ip; point lights fall off
  // with the spec's inverse square, f_att = 1 / d^2. Spot lights become point
  // lights (the cone is not modelled) and "range" is not applied.
  void addLight(int index, const glm::mat4& world, const std::string& where) {
    if (index < 0 || size_t(index) >= model_.lights.size())
      fail(source_, where + ": KHR_lights_punctual",
           "refers to light " + std::to_string(index) + ", which does not exist");
    const tinygltf::Light& source = model_.lights[size_t(index)];
    std::string lightWhere = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
    // A negative light would darken; the extension says 0 or more (candela or
    // lux). Past 1e6 (the colour's clamp, and the environments' limit) the
    // float products overflow.
    if (!(source.intensity >= 0.0 && source.intensity <= 1e6))
      fail(source_, lightWhere + ".intensity",
           gltf::numberText(source.intensity) + "; expected a number from 0 to 1000000");
    if (source.type != "directional" && source.type != "point" && source.type != "spot")
      fail(source_, lightWhere + ".type",
           "'" + source.type + "'; expected directional, point or spot");
    if (!source.color.empty() && source.color.size() != 3)
      fail(source_, lightWhere + ".color",
           std::to_string(source.color.size()) + " numbers; expected 3 (r, g, b)");
    Light light;
    glm::vec3 colour = glm::clamp(
        source.color.size() >= 3
            ? glm::vec3(float(source.color[0]), float(source.color[1]), float(source.color[2]))
            : glm::vec3(1.0f),
        0.0f, 1e6f);
    light.intensity = colour * std::max(float(source.intensity), 0.0f);
    if (source.type == "directional") {
      light.type = LightType::Directional;
      glm::vec3 direction = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
      light.direction =
          glm::length(direction) > 0.0f ? glm::normalize(direction) : glm::vec3(0.0f, -1.0f, 0.0f);
    } else {
      light.type = LightType::Point;
      light.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
      light.attenuation = glm::vec3(0.0f, 0.0f, 1.0f);
    }
    result_->lights.push_back(light);
  }

  const tinygltf::Model& model_;
  const std::string& source_;
  Scene& scene_;
  gltf::MaterialTable materials_;
  // (mesh, primitive, mirrored, TEXCOORD set)
  std::map<std::tuple<int, int, bool, int>, uint32_t> meshes_;
  std::set<int> visited_;
  std::map<uint32_t, Bounds> meshBounds_;  // each placed mesh's box, found once
  size_t placed_ = 0;                      // objects this file placed
  GltfImport* result_ = nullptr;
};

Scene sceneFromImport(Scene scene, GltfImport import, const std::string& source) {
  scene.lights = std::move(import.lights);
  if (scene.lights.size() > MAX_LIGHTS) scene.lights.resize(MAX_LIGHTS);
  if (import.camera) {
    scene.camera = *import.camera;
  } else {
    // Framing squares the scene's lengths: past ~1e19 they overflow a float.
    Bounds bounds = sceneBounds(scene);
    scene.camera = frameBounds(bounds);
    if (findCameraProblem(scene.camera)) {
      std::ostringstream extent;
      extent << "the scene spans (" << bounds.min.x << ", " << bounds.min.y << ", " << bounds.min.z
             << ") to (" << bounds.max.x << ", " << bounds.max.y << ", " << bounds.max.z
             << "), too far to frame a camera on";
      fail(source, "", extent.str() + "; expected coordinates within about 1e18 (or a camera)");
    }
  }
  if (scene.lights.empty()) scene.lights.push_back(defaultKeyLight(scene.camera));
  // glTF materials set ka = kd, so a dim ambient keeps unlit sides readable.
  scene.ambient = glm::vec3(0.15f);
  scene.background = glm::vec3(0.05f, 0.05f, 0.06f);
  return scene;
}

}  // namespace

GltfImport appendGltf(Scene& scene, const std::filesystem::path& path, const glm::mat4& parent) {
  std::vector<uint8_t> bytes = readFile(path);
  std::string source = path.string();
  tinygltf::Model model = parseModel(bytes, source, path.parent_path().string(),
                                     /* allowFiles= */ true, sceneTexels(scene));
  return NodeWalker(model, source, scene).walk(parent);
}

Scene loadGltfScene(const std::filesystem::path& path) {
  Scene scene;
  scene.name = path.stem().string();
  GltfImport import = appendGltf(scene, path);
  return sceneFromImport(std::move(scene), std::move(import), path.string());
}

Scene parseGltfScene(std::span<const uint8_t> bytes, const std::string& sourceName) {
  tinygltf::Model model = parseModel(bytes, sourceName, "", /* allowFiles= */ false, 0);
  Scene scene;
  scene.name = sourceName;
  GltfImport import = NodeWalker(model, sourceName, scene).walk(glm::mat4(1.0f));
  return sceneFromImport(std::move(scene), std::move(import), sourceName);
}

Bounds sceneBounds(const Scene& scene) {
  Bounds bounds{glm::vec3(0.0f), glm::vec3(0.0f)};
  bool first = true;
  for (const Object& object : scene.objects) {
    Bounds box = transformBounds(computeBounds(scene.meshes[object.mesh]), object.transform);
    bounds = first ? box : unite(bounds, box);
    first = false;
  }
  return bounds;
}

// A three-quarter view from the front (+z), a little above and to the
// right, at the nearest distance where all 8 corners of the box fall inside
// the 45 degree view, horizontally too for any aspect >= 1. A corner at
// (x, y) across and z towards the eye needs D >= z + max(|x|, |y|) / tan(fovy/2).
Camera frameBounds(const Bounds& worldBounds) {
  Camera camera;
  glm::vec3 c = centre(worldBounds);
  float radius = std::max(boundingRadius(worldBounds), 1e-4f);
  glm::vec3 back = glm::normalize(glm::vec3(0.5f, 0.35f, 1.0f));  // centre -> eye
  glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), back));
  glm::vec3 up = glm::cross(back, right);
  float tanHalf = std::tan(glm::radians(camera.fovyDegrees) * 0.5f);
  float distance = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    glm::vec3 p = glm::vec3(corner & 1 ? worldBounds.max.x : worldBounds.min.x,
                            corner & 2 ? worldBounds.max.y : worldBounds.min.y,
                            corner & 4 ? worldBounds.max.z : worldBounds.min.z) -
                  c;
    float across = std::max(std::abs(glm::dot(p, right)), std::abs(glm::dot(p, up)));
    distance = std::max(distance, glm::dot(p, back) + across / tanHalf);
  }
  distance = std::max(distance * 1.05f, radius * 1e-2f);  // a 5% margin
  camera.at = c;
  camera.eye = c + distance * back;
  camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
  camera.near = std::max(distance - radius, distance * 1e-3f) * 0.5f;
  camera.far = distance + radius * 2.0f;
  return camera;
}

// Key light: a directional light from over the camera's left shoulder.
Light defaultKeyLight(const Camera& camera) {
  glm::vec3 forward = glm::normalize(camera.at - camera.eye);
  glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  glm::vec3 up = glm::cross(right, forward);
  Light light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(forward - up + 0.5f * right);
  light.intensity = glm::vec3(1.0f);
  return light;
}

}  // namespace shadelab
