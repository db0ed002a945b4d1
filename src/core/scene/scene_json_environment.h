#pragma once
// The "environment" field of a scene file (documented at the top of
// scene_json.cpp). Private to scene_json*.cpp.
#include <filesystem>

#include "core/scene/environment.h"
#include "core/scene/scene_json_fields.h"

namespace shadelab::scene_json {

// The largest environment or sun intensity a scene may ask for: a sky of
// 3e38 came out NaN in every pixel (the half-float target tops out at 65504).
inline constexpr float kMaxEnvironmentIntensity = 1e6f;

// Image files are read now, relative to `folder` (the scene file's), so a
// missing or unreadable one is reported before anything renders.
Environment parseEnvironment(const Field& field, const std::filesystem::path& folder);

}  // namespace shadelab::scene_json
