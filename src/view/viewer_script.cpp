#include "view/viewer_script.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/image.h"
#include "core/scene/camera_path.h"

namespace shadelab {
namespace {

struct LineReader {
  std::string fileName;
  int line = 0;
  std::vector<std::string> words;

  [[noreturn]] void fail(const std::string& expected) const {
    std::string text;
    for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
    throw InputError(fileName + ":" + std::to_string(line) + ": '" + text + "': expected " +
                     expected);
  }
  void expectCount(size_t minimum, size_t maximum, const std::string& usage) const {
    if (words.size() < minimum || words.size() > maximum) fail(usage);
  }
  template <typename Number>
  Number number(size_t index, Number minimum, Number maximum, const std::string& usage) const {
    const std::string& word = words[index];
    Number value{};
    auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    // Written so that NaN (which from_chars reads) fails too.
    if (error != std::errc() || end != word.data() + word.size() ||
        !(value >= minimum && value <= maximum))
      fail(usage);
    return value;
  }
};

ScriptStep parseLine(const LineReader& reader, const std::vector<std::string>& keys) {
  const std::string& command = reader.words[0];
  ScriptStep step;
  step.line = reader.line;
  if (command == "key") {
    std::string usage = "'key K' with K one of";
    for (const std::string& key : keys) usage += " " + key;
    reader.expectCount(2, 2, usage);
    std::string name = reader.words[1];
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return std::toupper(c); });
    if (std::find(keys.begin(), keys.end(), name) == keys.end()) reader.fail(usage);
    step.kind = ScriptStep::Kind::Key;
    step.key = name[0];  // GLFW codes digits and letters as their ASCII upper case
  } else if (command == "frames") {
    const char* usage = "'frames N' with N in 1..1000000";
    reader.expectCount(2, 2, usage);
    step.kind = ScriptStep::Kind::Frames;
    step.count = reader.number<uint32_t>(1, 1, 1000000, usage);
  } else if (command == "drag") {
    const char* usage = "'drag X0 Y0 X1 Y1 [left|right|middle]' in window pixels";
    reader.expectCount(5, 6, usage);
    step.kind = ScriptStep::Kind::Drag;
    step.from = {reader.number<double>(1, -1e5, 1e5, usage),
                 reader.number<double>(2, -1e5, 1e5, usage)};
    step.to = {reader.number<double>(3, -1e5, 1e5, usage),
               reader.number<double>(4, -1e5, 1e5, usage)};
    if (reader.words.size() == 6) {
      const std::string& button = reader.words[5];
      if (button == "left")
        step.button = MouseButton::Left;
      else if (button == "right")
        step.button = MouseButton::Right;
      else if (button == "middle")
        step.button = MouseButton::Middle;
      else
        reader.fail(usage);
    }
  } else if (command == "scroll") {
    const char* usage = "'scroll N' with N a number of wheel steps in -100..100";
    reader.expectCount(2, 2, usage);
    step.kind = ScriptStep::Kind::Scroll;
    step.scroll = reader.number<float>(1, -100.0f, 100.0f, usage);
  } else if (command == "resize") {
    const char* usage = "'resize W H' with W and H in 1..8192";
    reader.expectCount(3, 3, usage);
    step.kind = ScriptStep::Kind::Resize;
    step.width = reader.number<uint32_t>(1, 1, 8192, usage);
    step.height = reader.number<uint32_t>(2, 1, 8192, usage);
  } else if (command == "screenshot") {
    reader.expectCount(2, 2, "'screenshot FILE.png'");
    step.kind = ScriptStep::Kind::Screenshot;
    step.path = reader.words[1];
    if (std::filesystem::path(step.path).extension() != ".png")
      reader.fail("'screenshot FILE.png' (a .png file)");
    try {
      checkOutputPath(step.path);
    } catch (const InputError& error) {
      reader.fail(std::string("a writable .png path (") + error.what() + ")");
    }
  } else if (command == "camera-path") {
    reader.expectCount(2, 2, "'camera-path FILE' (a camera path JSON file)");
    step.kind = ScriptStep::Kind::CameraPath;
    step.path = reader.words[1];
    // Read and checked now, so a bad file stops the session before it
    // starts; the cameras are made when the step runs, from the scene's.
    try {
      step.text = readInputFile(step.path, "camera path", kMaxTextInputBytes);
      parseCameraPath(step.text, step.path, Camera{});
    } catch (const InputError& error) {
      reader.fail(std::string("a readable camera path file (") + error.what() + ")");
    }
  } else {
    static const std::pair<const char*, ScriptStep::Kind> bare[] = {
        {"minimize", ScriptStep::Kind::Minimize},
        {"restore", ScriptStep::Kind::Restore},
        {"memory", ScriptStep::Kind::Memory},
        {"wait-reference", ScriptStep::Kind::WaitReference},
        {"quit", ScriptStep::Kind::Quit}};
    for (const auto& [name, kind] : bare) {
      if (command != name) continue;
      reader.expectCount(1, 1, "'" + command + "' with nothing after it");
      step.kind = kind;
      return step;
    }
    reader.fail(
        "a step: key, frames, drag, scroll, resize, minimize, restore, screenshot, "
        "memory, wait-reference, camera-path or quit");
  }
  return step;
}

}  // namespace

std::vector<ScriptStep> parseViewerScriptText(const std::string& text, const std::string& fileName,
                                              const std::vector<std::string>& keys) {
  std::vector<ScriptStep> steps;
  std::istringstream lines(text);
  std::string line;
  LineReader reader{fileName};
  bool minimized = false;
  while (std::getline(lines, line)) {
    ++reader.line;
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    reader.words.clear();
    for (std::string word; words >> word;) reader.words.push_back(word);
    if (reader.words.empty()) continue;
    steps.push_back(parseLine(reader, keys));
    ScriptStep::Kind kind = steps.back().kind;
    if (kind == ScriptStep::Kind::Screenshot && minimized)
      reader.fail("'restore' first: nothing is presented while minimised");
    if (kind == ScriptStep::Kind::Minimize) minimized = true;
    if (kind == ScriptStep::Kind::Restore) minimized = false;
  }
  return steps;
}

std::vector<ScriptStep> parseViewerScript(const std::filesystem::path& path,
                                          const std::vector<std::string>& keys) {
  std::string text = readInputFile(path, "--script", kMaxTextInputBytes);
  return parseViewerScriptText(text, path.string(), keys);
}

void checkScriptCameraPaths(const std::vector<ScriptStep>& steps, const std::string& fileName,
                            const Camera& sceneCamera) {
  for (const ScriptStep& step : steps) {
    if (step.kind != ScriptStep::Kind::CameraPath) continue;
    try {
      parseCameraPath(step.text, step.path, sceneCamera);
    } catch (const InputError& error) {
      throw InputError(fileName + ":" + std::to_string(step.line) + ": 'camera-path " + step.path +
                       "' with this scene's camera: " + error.what());
    }
  }
}

}  // namespace shadelab
