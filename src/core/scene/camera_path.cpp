#include "core/scene/camera_path.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/base/errors.h"
#include "core/base/json_nesting.h"
#include "core/scene/scene_json_fields.h"

namespace shadelab {
namespace {

[[noreturn]] void fail(const std::string& source, const std::string& field,
                       const std::string& what) {
  throw InputError(source + ": " + field + ": " + what);
}

std::string frameRange() {
  return "an integer from 1 to " + std::to_string(kMaxSequenceFrames);
}

glm::vec3 readVector(const nlohmann::json& value, const std::string& source,
                     const std::string& field) {
  if (!value.is_array() || value.size() != 3)
    fail(source, field, "expected an array of three numbers");
  glm::vec3 vector;
  for (int i = 0; i < 3; ++i) {
    // Finite as a float too: 1e39 is a finite double and an infinite float.
    if (!value[size_t(i)].is_number() || !std::isfinite(value[size_t(i)].get<float>()))
      fail(source, field + "[" + std::to_string(i) + "]", "expected a finite number");
    vector[i] = value[size_t(i)].get<float>();
  }
  return vector;
}

Camera readCamera(const nlohmann::json& value, const std::string& source, const std::string& where,
                  const Camera& base) {
  if (!value.is_object()) fail(source, where, "expected an object with eye, at, up, fovy");
  Camera camera = base;
  for (const auto& [key, field] : value.items()) {
    std::string name = where + "." + key;
    if (key == "eye") {
      camera.eye = readVector(field, source, name);
    } else if (key == "at") {
      camera.at = readVector(field, source, name);
    } else if (key == "up") {
      camera.up = readVector(field, source, name);
    } else if (key == "fovy") {
      if (!field.is_number() || !(field.get<double>() > 0.0 && field.get<double>() < 180.0))
        fail(source, name, "expected degrees between 0 and 180");
      camera.fovyDegrees = field.get<float>();
    } else {
      fail(source, name, "unknown field (expected eye, at, up, fovy)");
    }
  }
  if (std::optional<CameraProblem> problem = findCameraProblem(camera))
    fail(source, where + "." + problem->field,
         problem->problem + "; expected " + problem->expected);
  return camera;
}

Camera mixCameras(const Camera& a, const Camera& b, float t) {
  Camera camera = a;
  camera.eye = glm::mix(a.eye, b.eye, t);
  camera.at = glm::mix(a.at, b.at, t);
  camera.up = glm::mix(a.up, b.up, t);
  camera.fovyDegrees = glm::mix(a.fovyDegrees, b.fovyDegrees, t);
  return camera;
}

}  // namespace

std::vector<Camera> turntableCameras(const Camera& camera, int64_t frames) {
  if (frames < 1 || frames > int64_t(kMaxSequenceFrames))
    throw InputError("--turntable " + std::to_string(frames) + ": expected " + frameRange());
  glm::vec3 axis = glm::normalize(camera.up);
  std::vector<Camera> cameras;
  for (int64_t i = 0; i < frames; ++i) {
    float angle = 2.0f * glm::pi<float>() * float(i) / float(frames);
    glm::mat4 turn = glm::rotate(glm::mat4(1.0f), angle, axis);
    Camera turned = camera;
    turned.eye = camera.at + glm::vec3(turn * glm::vec4(camera.eye - camera.at, 0.0f));
    cameras.push_back(turned);
  }
  return cameras;
}

std::vector<Camera> parseCameraPath(const std::string& text, const std::string& source,
                                    const Camera& base) {
  checkJsonNesting(text, source);  // the parser recurses once per level
  nlohmann::json root = nlohmann::json::parse(text, scene_json::refuseDuplicateKeys(source), false);
  if (root.is_discarded()) fail(source, "JSON", "malformed (not valid JSON)");
  nlohmann::json keys = root;
  std::optional<int64_t> frames;
  std::string where = "";
  if (root.is_object()) {
    for (const auto& [key, field] : root.items())
      if (key != "frames" && key != "cameras")
        fail(source, key, "unknown field (expected frames, cameras)");
    if (!root.contains("cameras")) fail(source, "cameras", "missing (a list of cameras)");
    keys = root["cameras"];
    where = "cameras";
    if (root.contains("frames")) {
      const nlohmann::json& count = root["frames"];
      if (!count.is_number_integer() || count.get<int64_t>() < 1 ||
          count.get<int64_t>() > int64_t(kMaxSequenceFrames))
        fail(source, "frames", "expected " + frameRange());
      frames = count.get<int64_t>();
    }
  }
  if (!keys.is_array() || keys.empty())
    fail(source, where.empty() ? "the file" : where,
         "expected a non-empty list of cameras ({\"eye\": [x, y, z], \"at\": ..., \"up\": ..., "
         "\"fovy\": degrees})");
  if (keys.size() > kMaxSequenceFrames)
    fail(source, where.empty() ? "the file" : where,
         std::to_string(keys.size()) + " cameras; expected at most " +
             std::to_string(kMaxSequenceFrames) + " (a sequence's most frames)");
  std::vector<Camera> cameras;
  for (size_t i = 0; i < keys.size(); ++i)
    cameras.push_back(readCamera(keys[i], source, where + "[" + std::to_string(i) + "]", base));
  if (!frames || size_t(*frames) == cameras.size()) return cameras;
  if (size_t(*frames) < cameras.size())
    fail(source, "frames",
         std::to_string(*frames) + " is fewer than the " + std::to_string(cameras.size()) +
             " cameras to pass through");
  // The keys spread evenly: key k at frame k (N - 1) / (keys - 1).
  std::vector<Camera> path;
  for (int64_t i = 0; i < *frames; ++i) {
    if (cameras.size() == 1) {
      path.push_back(cameras[0]);
      continue;
    }
    float position = float(i) * float(cameras.size() - 1) / float(*frames - 1);
    size_t key = std::min(size_t(position), cameras.size() - 2);
    path.push_back(mixCameras(cameras[key], cameras[key + 1], position - float(key)));
    // Two good keys can pass through a bad camera: eyes on opposite sides
    // of `at` meet it halfway, opposite ups cancel.
    if (std::optional<CameraProblem> problem = findCameraProblem(path.back()))
      fail(source, "frames",
           "frame " + std::to_string(i + 1) + ", between " + where + "[" + std::to_string(key) +
               "] and " + where + "[" + std::to_string(key + 1) + "]: the camera's " +
               problem->field + ": " + problem->problem + "; expected " + problem->expected +
               " (add a camera between them)");
  }
  return path;
}

std::string sequenceFramePath(const std::string& output, uint32_t frame) {
  std::filesystem::path path(output);
  char number[16];
  std::snprintf(number, sizeof number, "-%04u", frame);
  return (path.parent_path() / (path.stem().string() + number + path.extension().string()))
      .string();
}

}  // namespace shadelab
