#pragma once
// Scripted viewer sessions (--script FILE), one step per line:
//   key K                  press key K (a bound key: 1-4, a letter)
//   frames N               draw N frames (while minimised: N idle ticks)
//   drag X0 Y0 X1 Y1 [left|right|middle]   window coordinates, top-left origin
//   scroll N               wheel steps, positive zooms in
//   resize W H             set the window size
//   minimize / restore
//   screenshot FILE.png    the next presented frame, as presented
//   memory                 print resident memory (VmRSS) and the frame count
//   wait-reference         draw frames until the split screen's traced
//                          reference (key X) is ready and measured
//   camera-path FILE       draw one frame per camera of a camera path file
//                          (render --camera-path's format; fields a camera
//                          leaves out keep the scene camera's); the camera
//                          stays at the last one
//   quit
// '#' starts a comment. The session ends after the last step.
#include <filesystem>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "view/window.h"

namespace shadelab {

struct ScriptStep {
  enum class Kind {
    Key,
    Frames,
    Drag,
    Scroll,
    Resize,
    Minimize,
    Restore,
    Screenshot,
    Memory,
    WaitReference,
    CameraPath,
    Quit
  };
  Kind kind = Kind::Quit;
  int key = 0;                    // Key: GLFW key code
  uint32_t count = 0;             // Frames
  glm::dvec2 from{0.0}, to{0.0};  // Drag, window coordinates
  MouseButton button = MouseButton::Left;
  float scroll = 0.0f;
  uint32_t width = 0, height = 0;  // Resize
  std::string path;                // Screenshot, CameraPath
  std::string text;                // CameraPath: the file, read and checked when parsed
  int line = 0;
};

// Throws InputError naming the file, the line and what was expected. `keys`
// are the names accepted after `key` (as typed: "1", "C").
std::vector<ScriptStep> parseViewerScript(const std::filesystem::path& path,
                                          const std::vector<std::string>& keys);
std::vector<ScriptStep> parseViewerScriptText(const std::string& text, const std::string& fileName,
                                              const std::vector<std::string>& keys);
// The camera-path steps made into cameras from the scene's camera (fields a
// path leaves out keep its values, which can make a camera unusable): throws
// InputError naming the script file, the line and the path's problem.
void checkScriptCameraPaths(const std::vector<ScriptStep>& steps, const std::string& fileName,
                            const Camera& sceneCamera);

}  // namespace shadelab
