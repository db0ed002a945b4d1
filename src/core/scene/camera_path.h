#pragma once
// Camera sequences for `render --turntable N` and `render --camera-path FILE`:
// the cameras of the frames, one per frame, computed before anything renders.
#include <string>
#include <vector>

#include "core/scene/scene.h"

namespace shadelab {

inline constexpr uint32_t kMaxSequenceFrames = 9999;  // frame numbers have four digits

// N cameras orbiting `camera.at` about `camera.up` (right-handed, counter-
// clockwise seen from above), frame i at 360 i / N degrees: the first frame
// is `camera` itself, the last one step short of it, so the loop closes.
// Throws InputError for N outside 1..kMaxSequenceFrames.
std::vector<Camera> turntableCameras(const Camera& camera, int64_t frames);

// A camera path file (JSON), `source` naming it in messages:
//   [ {"eye": [x,y,z], "at": [...], "up": [...], "fovy": deg}, ... ]
//     one frame per camera, as listed;
//   {"frames": N, "cameras": [ ...keys... ]}
//     N frames, the keys spread evenly over them and eye, at, up and fovy
//     interpolated linearly between neighbours (N >= the number of keys).
// A field a camera leaves out keeps `base`'s value (the scene's camera).
// Throws InputError naming the file, the field and what was expected.
std::vector<Camera> parseCameraPath(const std::string& text, const std::string& source,
                                    const Camera& base);

// "out/spin.png", 3 -> "out/spin-0003.png".
std::string sequenceFramePath(const std::string& output, uint32_t frame);

}  // namespace shadelab
