// The viewer's CPU side: window-to-view coordinates, the orbit / pan / zoom
// camera against the geometry it promises, the script parser and its error
// messages, and run-time GLSL compilation against the build's SPIR-V.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <thread>

#include "core/base/errors.h"
#include "core/trace/raytracer.h"
#include "core/vulkan/shader_table.h"
#include "passes/renderer.h"
#include "view/background_trace.h"
#include "view/camera_controller.h"
#include "view/glsl_compiler.h"
#include "view/viewer_script.h"
#include "view/window.h"

namespace shadelab {
namespace {

float angleBetween(glm::vec3 a, glm::vec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

TEST(WindowToView, FlipsYOnce) {
  EXPECT_EQ(windowToView({0.0, 0.0}, {320, 180}), glm::vec2(0.0f, 180.0f));
  EXPECT_EQ(windowToView({10.0, 170.0}, {320, 180}), glm::vec2(10.0f, 10.0f));
}

Camera frontCamera() {
  Camera camera;
  camera.eye = {0.0f, 0.0f, 5.0f};
  camera.at = {0.0f, 0.0f, 0.0f};
  return camera;
}

TEST(CameraController, UnmovedCameraIsTheSceneCamera) {
  Camera camera = frontCamera();
  CameraController controller(camera);
  EXPECT_EQ(controller.camera().eye, camera.eye);
  EXPECT_EQ(controller.camera().at, camera.at);
}

TEST(CameraController, HorizontalDragOfHalfTheHeightTurnsNinetyDegrees) {
  CameraController controller(frontCamera());
  controller.orbit({90.0f, 0.0f}, 180.0f);
  glm::vec3 eye = controller.camera().eye;
  EXPECT_NEAR(glm::length(eye), 5.0f, 1e-4f);  // distance to the target kept
  // Dragging right turns the scene right: the eye goes to the left (-x).
  EXPECT_NEAR(eye.x, -5.0f, 1e-4f);
  EXPECT_NEAR(eye.z, 0.0f, 1e-4f);
}

TEST(CameraController, DraggingUpLowersTheEyeAndStopsShortOfThePole) {
  CameraController controller(frontCamera());
  controller.orbit({0.0f, 30.0f}, 180.0f);  // 30 degrees
  glm::vec3 eye = controller.camera().eye;
  EXPECT_NEAR(std::asin(eye.y / glm::length(eye)), -glm::radians(30.0f), 1e-4f);
  controller.orbit({0.0f, 1000.0f}, 180.0f);
  eye = controller.camera().eye;
  EXPECT_NEAR(angleBetween(eye, {0.0f, -1.0f, 0.0f}), glm::radians(1.0f), 1e-3f);
  EXPECT_NEAR(glm::length(eye), 5.0f, 1e-3f);
}

TEST(CameraController, PanMovesTargetWithTheCursorAtItsDepth) {
  Camera camera = frontCamera();
  CameraController controller(camera);
  controller.pan({18.0f, 0.0f}, 180.0f);
  // View height at the target: 2 d tan(fovy/2); 18 of 180 pixels is a tenth.
  float expected = 0.1f * 2.0f * 5.0f * std::tan(glm::radians(camera.fovyDegrees) * 0.5f);
  EXPECT_NEAR(controller.camera().at.x, -expected, 1e-5f);
  EXPECT_NEAR(controller.camera().eye.x, -expected, 1e-5f);
  EXPECT_EQ(controller.camera().eye.z, 5.0f);
}

TEST(CameraController, ZoomScalesDistanceByPointNinePerStep) {
  CameraController controller(frontCamera());
  controller.zoom(2.0f);
  EXPECT_NEAR(glm::length(controller.camera().eye), 5.0f * 0.81f, 1e-5f);
  controller.zoom(-2.0f);
  EXPECT_NEAR(glm::length(controller.camera().eye), 5.0f, 1e-5f);
  controller.zoom(100.0f);  // never through the target
  EXPECT_GE(glm::length(controller.camera().eye), 2.0f * frontCamera().near - 1e-6f);
  // Out without end: the point looked at stays half-way to the far plane.
  for (int i = 0; i < 1000; ++i) controller.zoom(-100.0f);
  EXPECT_NEAR(glm::length(controller.camera().eye), 0.5f * frontCamera().far,
              1e-3f * frontCamera().far);
}

const std::vector<std::string> kKeys = {"1", "2", "C", "P"};

TEST(ViewerScript, ParsesEveryStep) {
  std::vector<ScriptStep> steps = parseViewerScriptText(
      "# comment\nkey c\nframes 10\ndrag 1 2 3 4\ndrag 1 2 3 4 right\nscroll -1.5\n"
      "resize 800 600\nminimize\nrestore\nmemory\nscreenshot a.png  # trailing\nquit\n",
      "s.txt", kKeys);
  ASSERT_EQ(steps.size(), 11u);
  EXPECT_EQ(steps[0].kind, ScriptStep::Kind::Key);
  EXPECT_EQ(steps[0].key, 'C');
  EXPECT_EQ(steps[0].line, 2);
  EXPECT_EQ(steps[1].count, 10u);
  EXPECT_EQ(steps[2].button, MouseButton::Left);
  EXPECT_EQ(steps[2].to, glm::dvec2(3.0, 4.0));
  EXPECT_EQ(steps[3].button, MouseButton::Right);
  EXPECT_EQ(steps[4].scroll, -1.5f);
  EXPECT_EQ(steps[5].width, 800u);
  EXPECT_EQ(steps[5].height, 600u);
  EXPECT_EQ(steps[9].path, "a.png");
  EXPECT_EQ(steps[10].kind, ScriptStep::Kind::Quit);
}

std::string parseError(const std::string& text) {
  try {
    parseViewerScriptText(text, "bad.txt", kKeys);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ViewerScript, BadLinesNameFileLineAndWhatWasExpected) {
  EXPECT_EQ(parseError("frames 1\nkey X\n"),
            "bad.txt:2: 'key X': expected 'key K' with K one of 1 2 C P");
  EXPECT_EQ(parseError("frames ten"),
            "bad.txt:1: 'frames ten': expected 'frames N' with N in 1..1000000");
  EXPECT_EQ(parseError("frames 0"),
            "bad.txt:1: 'frames 0': expected 'frames N' with N in 1..1000000");
  EXPECT_NE(parseError("drag 1 2 3").find("bad.txt:1: 'drag 1 2 3': expected 'drag X0 Y0 X1 Y1"),
            std::string::npos);
  EXPECT_NE(parseError("drag 1 2 3 4 thumb").find("expected 'drag"), std::string::npos);
  EXPECT_NE(parseError("resize 0 10").find("W and H in 1..8192"), std::string::npos);
  EXPECT_NE(parseError("quit now").find("'quit' with nothing after it"), std::string::npos);
  EXPECT_NE(parseError("wait-reference 5").find("'wait-reference' with nothing after it"),
            std::string::npos);
  EXPECT_NE(parseError("\n\njump").find("bad.txt:3: 'jump': expected a step"), std::string::npos);
  EXPECT_EQ(parseError("minimize\nscreenshot a.png\n"),
            "bad.txt:2: 'screenshot a.png': expected 'restore' first: nothing is presented while "
            "minimised");
  EXPECT_NE(parseError("screenshot a.jpg").find("(a .png file)"), std::string::npos);
  EXPECT_NE(parseError("screenshot /no/such/dir/a.png").find("bad.txt:1:"), std::string::npos);
}

TEST(ViewerScript, WaitReferenceIsAStep) {
  std::vector<ScriptStep> steps = parseViewerScriptText("key C\nwait-reference\n", "s.txt", kKeys);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[1].kind, ScriptStep::Kind::WaitReference);
}

// camera-path FILE reads and checks the file when the script is parsed, so
// a bad path stops the session before its first frame.
TEST(ViewerScript, CameraPathIsReadWhenParsed) {
  std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "script";
  std::filesystem::create_directories(dir);
  std::string good = (dir / "path.json").string(), bad = (dir / "bad.json").string();
  std::ofstream(good) << R"({"frames": 4, "cameras": [{"eye": [0, 1, 5]}, {"eye": [5, 1, 0]}]})";
  std::ofstream(bad) << R"({"frames": 1, "cameras": [{"eye": [0, 1, 5]}, {"eye": [5, 1, 0]}]})";
  std::vector<ScriptStep> steps =
      parseViewerScriptText("camera-path " + good + "\nframes 1\n", "s.txt", kKeys);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].kind, ScriptStep::Kind::CameraPath);
  EXPECT_EQ(steps[0].path, good);
  EXPECT_NE(steps[0].text.find("\"frames\": 4"), std::string::npos);
  EXPECT_NE(
      parseError("camera-path " + bad)
          .find("bad.txt:1: 'camera-path " + bad + "': expected a readable camera path file ("),
      std::string::npos)
      << parseError("camera-path " + bad);
  EXPECT_NE(parseError("camera-path " + (dir / "none.json").string()).find("none.json"),
            std::string::npos);
  EXPECT_NE(parseError("camera-path").find("'camera-path FILE'"), std::string::npos);
  // A path that is fine on its own but not with this scene's camera: its
  // eye straight above the scene's look-at point, along the scene's up.
  std::string above = (dir / "above.json").string();
  std::ofstream(above) << R"([{"eye": [0, 10, -12]}])";
  std::vector<ScriptStep> script =
      parseViewerScriptText("frames 1\ncamera-path " + above + "\n", "s.txt", kKeys);
  Camera scene;
  scene.eye = {0.0f, 2.0f, 6.0f};
  scene.at = {0.0f, 0.0f, -12.0f};
  EXPECT_NO_THROW(checkScriptCameraPaths(script, "s.txt", Camera{}));
  try {
    checkScriptCameraPaths(script, "s.txt", scene);
    ADD_FAILURE() << "the scene's camera makes the path's camera unusable";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("s.txt:2: 'camera-path " + above + "'"),
              std::string::npos)
        << error.what();
  }
}

// Until a background trace is collected (no clock: it finishes when it does).
bool collectWhenDone(BackgroundTrace& trace) {
  while (trace.state() == BackgroundTrace::State::Tracing)
    if (trace.collect())
      return true;
    else
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return false;
}

// X's reference: what the thread hands over is the tracer's own image of the
// scene copy, bit for bit (sRGB, as compare measures); the must-fail twin:
// another camera's trace is not it.
TEST(BackgroundTrace, FinishedTraceIsTheTracersImage) {
  Scene scene = builtinScene("default");
  BackgroundTrace trace;
  trace.start(scene, 48, 27, 4);
  ASSERT_TRUE(collectWhenDone(trace)) << trace.error();
  EXPECT_EQ(trace.state(), BackgroundTrace::State::Ready);
  EXPECT_FALSE(trace.collect());  // once per trace
  TraceSettings settings;
  settings.width = 48;
  settings.height = 27;
  settings.samplesPerPixel = 4;
  ImageU8 expected = encodeSrgb8(RayTracer(scene).render(settings).image);
  EXPECT_EQ(trace.image().pixels, expected.pixels);
  Scene moved = scene;
  moved.camera.eye.x += 1.0f;
  trace.start(moved, 48, 27, 4);
  ASSERT_TRUE(collectWhenDone(trace)) << trace.error();
  EXPECT_NE(trace.image().pixels, expected.pixels);
}

// A stale trace (the camera moved on) is cancelled: nothing is handed over,
// and the next one runs to the end.
TEST(BackgroundTrace, CancelledTraceHandsNothingOver) {
  Scene scene = builtinScene("default");
  BackgroundTrace trace;
  trace.start(scene, 1280, 720, 64);  // minutes if it ran: cancel must stop it
  trace.cancel();
  EXPECT_EQ(trace.state(), BackgroundTrace::State::Idle);
  EXPECT_FALSE(trace.collect());
  trace.start(scene, 1280, 720, 64);
  trace.start(scene, 16, 9, 1);  // replaces the running one
  ASSERT_TRUE(collectWhenDone(trace)) << trace.error();
  EXPECT_EQ(trace.image().width, 16u);
  EXPECT_EQ(trace.progress(), 1.0f);
}

// Every row of the shader table, the ones compiled with defines included.
TEST(GlslCompiler, RunTimeSpirvEqualsTheBuildsSpirv) {
  // The forward pass reloads 8 stage variants, plain and textured, the 6 of
  // flat and Gouraud with shadows and the 2 of Phong with shadow coordinates,
  // plain and textured.
  EXPECT_EQ(Renderer::shaderVariants().size(), 32u);
  for (const ShaderVariant& variant : shaderTable()) {
    GlslCompileResult result = compileGlsl(SHADELAB_SHADER_SOURCE_DIR, variant);
    ASSERT_TRUE(result.ok()) << result.log;
    EXPECT_TRUE(std::equal(result.spirv.begin(), result.spirv.end(), variant.spirv.begin(),
                           variant.spirv.end()))
        << variant.name << ": " << result.spirv.size() << " words at run time, "
        << variant.spirv.size() << " from the build";
  }
}

// The defines reach the preprocessor: a body that refuses to compile without them.
TEST(GlslCompiler, DefinesReachThePreprocessor) {
  std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "glsl";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "needs_defines.frag")
      << "#version 460\n#if !defined(FIRST) || !defined(SECOND)\n#error missing define\n#endif\n"
         "void main() {}\n";
  const std::string_view both[] = {"FIRST", "SECOND"};
  ShaderVariant variant{"needs_defines", VK_SHADER_STAGE_FRAGMENT_BIT, "needs_defines.frag", both};
  EXPECT_TRUE(compileGlsl(dir, variant).ok());
  variant.defines = std::span(both).first(1);
  GlslCompileResult result = compileGlsl(dir, variant);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.log.find("missing define"), std::string::npos) << result.log;
}

TEST(GlslCompiler, ErrorsNameFileAndLine) {
  std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "glsl";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "broken.frag") << "#version 460\nvoid main() {\n  undefinedThing = 1.0;\n}\n";
  const std::string_view defines[] = {"SOME_DEFINE"};  // a preamble must not shift the line
  GlslCompileResult result =
      compileGlsl(dir, {"broken", VK_SHADER_STAGE_FRAGMENT_BIT, "broken.frag", defines});
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.log.find("broken.frag:3"), std::string::npos) << result.log;
  EXPECT_NE(result.log.find("undefinedThing"), std::string::npos) << result.log;
  EXPECT_FALSE(compileGlsl(dir, {"missing", VK_SHADER_STAGE_FRAGMENT_BIT, "missing.frag"}).ok());
}

}  // namespace
}  // namespace shadelab
