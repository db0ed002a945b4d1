// The viewer in a real X window (ctest runs this program under its own Xvfb,
// tests/run_with_xvfb.sh): scripts drive `shadelab view`, and what it
// presented is compared with headless renders of the same state.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <string>

#include "core/scene/lod.h"
#include "core/scene/scene.h"
#include "core/scene/scene_json.h"
#include "gpu_test_support.h"
#include "run_command.h"
#include "view/camera_controller.h"
#include "view/glsl_compiler.h"

namespace shadelab::test {
namespace {
namespace fs = std::filesystem;

constexpr uint32_t kWidth = 320;
constexpr uint32_t kHeight = 180;

class Viewer : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run through tests/run_with_xvfb.sh";
    dir = fs::path(testOutputDir()) / "viewer" /
          ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  // Runs `view` on a script; screenshot names in it are relative to the test folder.
  CommandResult view(const std::string& script, const std::string& options = "",
                     const std::string& environment = "", const std::string& size = "320x180") {
    std::ofstream(path("script.txt")) << script;
    // The headless renders compared against use FrameSettings' defaults,
    // shadows off and levels of detail off; the viewer's are hard and auto,
    // so pin them unless a test sets them.
    std::string shadows = options.find("--shadows") == std::string::npos ? " --shadows off" : "";
    std::string lod = options.find("--lod") == std::string::npos ? " --lod off" : "";
    return run("view " + options + shadows + lod + " --size " + size +
                   " --present immediate --script " + path("script.txt"),
               "cd " + dir.string() + " &&" + environment);
  }
  ImageU8 headless(Scene scene, ShadingModel model, std::vector<ShadingModel> split = {}) {
    RenderSettings settings{kWidth, kHeight, model};
    settings.splitModels = std::move(split);
    return render(scene, settings);
  }
  fs::path dir;
};

// The viewer's default, --lod auto at 0.5 px, draws what a headless render
// with the same setting draws (the first frame has no history; a still
// view keeps its levels), and on the default scene it does take coarser
// levels (the overlay's count is checked by the headless stats).
TEST_F(Viewer, LevelsOfDetailMatchHeadlessRenderWithTheSameBound) {
  CommandResult r = view("key O\nframes 3\nscreenshot lod.png\n", "--lod auto");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Scene scene = builtinScene("default");
  RenderSettings settings{kWidth, kHeight, ShadingModel::Phong};
  settings.lod = true;
  RenderResult result = renderer().renderToImage(scene, settings);
  EXPECT_GT(result.stats.coarserDraws, 0u);
  ImageU8 shot = readImageU8(path("lod.png"));
  ImageU8 withLevels = encodeSrgb8(result.image);
  EXPECT_TRUE(matchesImage(withLevels, shot));
  // Must fail: the full meshes draw another image (within the golden
  // tolerance at 0.5 px, which is the point of the bound), so the shot is
  // measured closer to the render with levels than to the one without.
  double toLevels = compareImages(withLevels, shot).rmse;
  double toFull = compareImages(headless(scene, ShadingModel::Phong), shot).rmse;
  std::printf("lod shot: RMSE %.3f to the render with levels, %.3f to the full one\n", toLevels,
              toFull);
  EXPECT_LT(2.0 * toLevels, toFull);
}

// The key help at 640x360 leaves room for the message line under it: the
// message (drawn in its yellow, which the default scene does not show) is a
// whole line of text inside the window. Before, the help's table was sized
// without the message and its rows' padding, and the message fell off the
// window's bottom edge (no yellow row above the last 8 pixels).
TEST_F(Viewer, KeyHelpLeavesTheMessageInsideTheWindow) {
  CommandResult r = view("key S\nkey H\nframes 3\nscreenshot help.png\n", "", "", "640x360");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("view: shadows: hard"), std::string::npos) << r.output;
  const ImageU8 shot = readImageU8(path("help.png"));
  ASSERT_EQ(shot.width, 640u);
  uint32_t top = shot.height, bottom = 0;
  for (uint32_t y = 0; y < shot.height; ++y)
    for (uint32_t x = 0; x < shot.width; ++x) {
      const uint8_t* p = &shot.pixels[(size_t(y) * shot.width + x) * 4];
      if (p[0] >= 230 && p[1] >= 180 && p[1] <= 235 && p[2] <= 110) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  ASSERT_LT(top, shot.height) << "no message pixels";
  EXPECT_GE(bottom - top + 1, 8u) << "the message is cut: rows " << top << ".." << bottom;
  EXPECT_LT(bottom, shot.height - 8) << "the message reaches the window's edge";
}

TEST_F(Viewer, EachShadingModelMatchesHeadlessRender) {
  CommandResult r = view(
      "key O\n"  // overlay off: the presented frame is the scene alone
      "key 1\nframes 2\nscreenshot flat.png\n"
      "key 2\nframes 2\nscreenshot gouraud.png\n"
      "key 3\nframes 2\nscreenshot phong.png\n"
      "key 4\nframes 2\nscreenshot blinn-phong.png\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Scene scene = builtinScene("default");
  std::map<ShadingModel, ImageU8> shots;
  for (ShadingModel model :
       {ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong, ShadingModel::BlinnPhong}) {
    std::string name(shadingModelName(model));
    shots[model] = readImageU8(path(name + ".png"));
    EXPECT_TRUE(matchesImage(headless(scene, model), shots[model])) << name;
    EXPECT_TRUE(matchesImage(loadGolden("default-" + name), shots[model])) << name;
  }
  // The models differ where they should: every pair by a measured margin.
  double flatRmse = compareImages(shots[ShadingModel::Phong], shots[ShadingModel::Flat]).rmse;
  double gouraudRmse = compareImages(shots[ShadingModel::Phong], shots[ShadingModel::Gouraud]).rmse;
  double blinnRmse =
      compareImages(shots[ShadingModel::Phong], shots[ShadingModel::BlinnPhong]).rmse;
  std::printf("screenshot RMSE against phong: flat %.2f, gouraud %.2f, blinn-phong %.2f\n",
              flatRmse, gouraudRmse, blinnRmse);
  EXPECT_GT(flatRmse, 1.0);
  EXPECT_GT(gouraudRmse, 0.5);
  EXPECT_GT(blinnRmse, 0.5);
  // Must-fail twin: a screenshot of another model is rejected by the same tolerance.
  EXPECT_FALSE(matchesImage(headless(scene, ShadingModel::Phong), shots[ShadingModel::Flat]));
  EXPECT_FALSE(matchesImage(headless(scene, ShadingModel::Phong), shots[ShadingModel::Gouraud]));
}

TEST_F(Viewer, OrbitPanAndZoomMatchHeadlessRenderOfTheMovedCamera) {
  CommandResult r = view(
      "key O\ndrag 100 100 160 80\ndrag 160 90 150 100 right\nscroll 2\n"
      "frames 2\nscreenshot moved.png\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Scene scene = builtinScene("default");
  CameraController camera(scene.camera);
  // Window coordinates are y down; the controller takes y up.
  camera.orbit({60.0f, 20.0f}, float(kHeight));
  camera.pan({-10.0f, -10.0f}, float(kHeight));
  camera.zoom(2.0f);
  Scene moved = scene;
  moved.camera = camera.camera();
  ImageU8 shot = readImageU8(path("moved.png"));
  EXPECT_TRUE(matchesImage(headless(moved, ShadingModel::Phong), shot));
  EXPECT_FALSE(matchesImage(headless(scene, ShadingModel::Phong), shot));  // it did move
}

// A view found by hand renders headless: V prints the camera as options, the
// screenshot's sidecar JSON holds the same line, and `render` with it draws
// what the window showed.
TEST_F(Viewer, PrintedCameraRendersTheSameViewHeadless) {
  CommandResult r =
      view("key O\ndrag 100 100 170 70\nscroll 2\nkey V\nframes 2\nscreenshot found.png\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(r.output, match, std::regex("camera: (--eye [^\n]*)\n")))
      << r.output;
  std::string line = match[1];
  std::ifstream sidecar(path("found.json"));
  std::string json((std::istreambuf_iterator<char>(sidecar)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"options\": \"" + line + "\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"scene\": \"default\""), std::string::npos) << json;
  CommandResult rendered =
      run("render default " + line + " --shadows off --size 320x180 -o " + path("headless.png"));
  ASSERT_EQ(rendered.exitCode, 0) << rendered.output;
  ImageU8 shot = readImageU8(path("found.png"));
  EXPECT_TRUE(matchesImage(readImageU8(path("headless.png")), shot));
  // Must-fail twin: the unmoved camera's render is not what the window showed.
  EXPECT_FALSE(matchesImage(headless(builtinScene("default"), ShadingModel::Phong), shot));
}

// Keys that are a script's last steps, or come right before `quit`, are
// still handled, with one more frame drawn for them. (They were
// dropped with the script's end; the summary then read "median of the last
// 0: 0.000 ms" instead of saying nothing was timed.)
TEST_F(Viewer, KeysJustBeforeTheScriptEndsAreHandled) {
  for (const char* script : {"frames 2\nkey V\nquit\n", "frames 2\nkey V\n"}) {
    CommandResult r = view(script);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("camera: --eye [^\n]*\n")))
        << script << r.output;
    EXPECT_EQ(r.output.find("median of the last 0"), std::string::npos) << r.output;
  }
  // A last P gets the frame it needs to write its screenshot.
  CommandResult shot = view("frames 2\nkey P\n");
  ASSERT_EQ(shot.exitCode, 0) << shot.output;
  EXPECT_TRUE(fs::exists(path("shadelab-screenshot-1.png"))) << shot.output;
  // Twin: a script without the key prints no camera.
  CommandResult r = view("frames 2\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("camera: --eye"), std::string::npos) << r.output;
}

TEST_F(Viewer, ZeroKeyPutsTheCameraBack) {
  CommandResult r =
      view("key O\ndrag 100 100 160 80\nscroll 3\nkey 0\nframes 2\nscreenshot back.png\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(matchesImage(headless(builtinScene("default"), ShadingModel::Phong),
                           readImageU8(path("back.png"))));
}

TEST_F(Viewer, SplitScreenMatchesHeadlessSplitAndReportsErrors) {
  CommandResult r = view("key O\nkey C\nframes 3\nscreenshot split.png\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::vector<ShadingModel> models = {ShadingModel::Flat, ShadingModel::Gouraud,
                                      ShadingModel::Phong, ShadingModel::BlinnPhong};
  ImageU8 shot = readImageU8(path("split.png"));
  ImageU8 expected = headless(builtinScene("default"), ShadingModel::Phong, models);
  EXPECT_TRUE(matchesImage(expected, shot));
  EXPECT_FALSE(matchesImage(headless(builtinScene("default"), ShadingModel::Phong), shot));
  // The errors the viewer reports are those of the headless columns (80
  // pixels wide each) against the Phong column.
  auto column = [&](uint32_t index) {
    ImageU8 part(kWidth / 4, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y)
      for (uint32_t x = 0; x < kWidth / 4; ++x)
        part.set(x, y, expected.at(index * kWidth / 4 + x, y));
    return part;
  };
  for (uint32_t i : {0u, 1u, 3u}) {
    std::string name(shadingModelName(models[i]));
    std::smatch match;
    ASSERT_TRUE(std::regex_search(r.output, match, std::regex(" " + name + R"( RMSE ([0-9.]+) )")))
        << name << "\n"
        << r.output;
    double expectedRmse = compareImages(column(2), column(i)).rmse;
    EXPECT_GT(expectedRmse, 0.5) << name;
    EXPECT_NEAR(std::stod(match[1]), expectedRmse, 0.01) << name;
  }
}

// X measures the split columns against the CPU tracer's image, traced in the
// background: what the viewer reports is what `compare` reports for the same
// view (80x180 columns, 4 spp, hard shadows on both sides; equal here,
// within 1e-3 in FLIP and 0.05 in RMSE for other Mesa versions). After a
// drag the reference is traced again for the moved camera, and its numbers
// are the moved view's, not the first's (the must-fail twin: a stale
// reference would match the first compare instead).
TEST_F(Viewer, SplitScreenReferenceMatchesCompareForTheSameView) {
  CommandResult r =
      view("key X\nwait-reference\nkey V\ndrag 100 100 150 80\nwait-reference\nkey V\nframes 1\n",
           "--shadows hard");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // "flat FLIP 0.1094 RMSE 19.908 ..." per model, per reference traced.
  std::vector<std::map<std::string, std::pair<double, double>>> measured;
  std::regex line("split-screen error against the traced reference \\(80x180, 4 spp\\):([^\n]*)");
  std::regex entry(" ([a-z-]+) FLIP ([0-9.]+) RMSE ([0-9.]+)");
  for (auto it = std::sregex_iterator(r.output.begin(), r.output.end(), line);
       it != std::sregex_iterator(); ++it) {
    std::string numbers = (*it)[1];
    measured.emplace_back();
    for (auto e = std::sregex_iterator(numbers.begin(), numbers.end(), entry);
         e != std::sregex_iterator(); ++e)
      measured.back()[(*e)[1]] = {std::stod((*e)[2]), std::stod((*e)[3])};
  }
  ASSERT_EQ(measured.size(), 2u) << r.output;  // one per camera
  std::vector<std::string> cameras;
  std::regex printed("camera: (--eye [^\n]*)\n");
  for (auto it = std::sregex_iterator(r.output.begin(), r.output.end(), printed);
       it != std::sregex_iterator(); ++it)
    cameras.push_back((*it)[1]);
  ASSERT_EQ(cameras.size(), 2u) << r.output;
  EXPECT_NE(cameras[0], cameras[1]);
  auto compareFlip = [&](const std::string& camera, const std::string& name) {
    CommandResult c = run("compare default " + camera + " --size 80x180 --shadows hard -o " +
                          path(name + ".png"));
    EXPECT_EQ(c.exitCode, 0) << c.output;
    std::map<std::string, std::pair<double, double>> numbers;
    std::ifstream file(path(name + ".json"));
    std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::regex mode(
        "\"flip\": ([0-9.e-]+),[^}]*\"mode\": \"([a-z-]+)\",[^}]*\"rmse\": ([0-9.e-]+)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), mode);
         it != std::sregex_iterator(); ++it)
      numbers[(*it)[2]] = {std::stod((*it)[1]), std::stod((*it)[3])};
    return numbers;
  };
  for (size_t view = 0; view < 2; ++view) {
    auto expected = compareFlip(cameras[view], "compare" + std::to_string(view));
    ASSERT_EQ(expected.size(), 4u);
    for (const auto& [model, flipAndRmse] : expected) {
      ASSERT_TRUE(measured[view].count(model)) << model << "\n" << r.output;
      EXPECT_NEAR(measured[view][model].first, flipAndRmse.first, 1e-3) << model << " " << view;
      EXPECT_NEAR(measured[view][model].second, flipAndRmse.second, 0.05) << model << " " << view;
    }
  }
  // The moved view's numbers are its own: the first view's are well apart
  // (blinn-phong: 0.0500 and 0.0401 as measured).
  double apart = 0.0;
  for (const auto& [model, flipAndRmse] : measured[0])
    apart = std::max(apart, std::abs(measured[1][model].first - flipAndRmse.first));
  EXPECT_GT(apart, 5e-3);
  EXPECT_NE(r.output.find("reference traced in"), std::string::npos) << r.output;
}

// E toggles the environment term and the skybox: each state matches the
// headless render with --env on / off, and the two differ.
TEST_F(Viewer, EnvironmentToggleMatchesHeadlessRender) {
  CommandResult r = view(
      "key O\nframes 2\nscreenshot env-on.png\nkey E\nframes 2\nscreenshot env-off.png\n", "env");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("environment mapping off"), std::string::npos) << r.output;
  Scene scene = builtinScene("env");
  ImageU8 on = readImageU8(path("env-on.png"));
  ImageU8 off = readImageU8(path("env-off.png"));
  RenderSettings settings{kWidth, kHeight, ShadingModel::Phong};
  EXPECT_TRUE(matchesImage(render(scene, settings), on));
  settings.environment = false;
  EXPECT_TRUE(matchesImage(render(scene, settings), off));
  EXPECT_FALSE(matchesImage(on, off));
}

TEST_F(Viewer, AutoTessellationMatchesHeadlessTessAuto) {
  CommandResult r = view("key O\nkey A\nframes 2\nscreenshot auto.png\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("automatic tessellation for this view"), std::string::npos) << r.output;
  Scene scene = builtinScene("default");
  tessellateForView(scene, ViewSize{scene.camera, kWidth, kHeight}, 0.5f);
  ImageU8 shot = readImageU8(path("auto.png"));
  EXPECT_TRUE(matchesImage(headless(scene, ShadingModel::Phong), shot));
}

// view takes the render options it can honour: --tess auto, --env, --filter,
// --bump, --mip-tint start the viewer where the keys would take it.
TEST_F(Viewer, RenderOptionsSetTheInitialState) {
  CommandResult r = view("key O\nframes 2\nscreenshot start.png\n",
                         "mip-plane --tess auto --filter nearest --mip-tint --bump off --env off");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Scene scene = builtinScene("mip-plane");
  tessellateForView(scene, ViewSize{scene.camera, kWidth, kHeight}, 0.5f);
  RenderSettings settings{kWidth, kHeight, ShadingModel::Phong};
  settings.textures.filterOverride = TextureFilter::Nearest;
  settings.textures.mipTint = true;
  settings.textures.bump = false;
  settings.environment = false;
  ImageU8 shot = readImageU8(path("start.png"));
  EXPECT_TRUE(matchesImage(render(scene, settings), shot));
  settings.textures.mipTint = false;  // must-fail twin: the options did change the image
  EXPECT_FALSE(matchesImage(render(scene, settings), shot));
}

TEST_F(Viewer, TextureKeysMatchHeadlessRendersWithTheSameOptions) {
  CommandResult bump = view("key O\nkey B\nframes 2\nscreenshot flat-bump.png\n", "bump");
  ASSERT_EQ(bump.exitCode, 0) << bump.output;
  CommandResult mip = view(
      "key O\nkey F\nframes 2\nscreenshot nearest.png\nkey F\nkey F\nkey M\n"
      "frames 2\nscreenshot tint.png\n",
      "mip-plane");
  ASSERT_EQ(mip.exitCode, 0) << mip.output;
  EXPECT_NE(mip.output.find("texture filter: nearest"), std::string::npos) << mip.output;
  RenderSettings settings{kWidth, kHeight, ShadingModel::Phong};
  settings.textures.bump = false;
  ImageU8 flatBump = readImageU8(path("flat-bump.png"));
  EXPECT_TRUE(matchesImage(render(builtinScene("bump"), settings), flatBump));
  settings.textures.bump = true;  // must-fail twin: bump mapping on looks different
  EXPECT_FALSE(matchesImage(render(builtinScene("bump"), settings), flatBump));

  settings.textures.filterOverride = TextureFilter::Nearest;
  EXPECT_TRUE(
      matchesImage(render(builtinScene("mip-plane"), settings), readImageU8(path("nearest.png"))));
  settings.textures.filterOverride = TextureFilter::Trilinear;
  settings.textures.mipTint = true;
  ImageU8 tint = readImageU8(path("tint.png"));
  EXPECT_TRUE(matchesImage(render(builtinScene("mip-plane"), settings), tint));
  settings.textures.mipTint = false;
  EXPECT_FALSE(matchesImage(render(builtinScene("mip-plane"), settings), tint));
}

// Keys that change only per-frame settings upload nothing: the scene's
// geometry, textures and environment cube stay as uploaded at start. The
// count the viewer prints is the renderer's; T, which does re-tessellate and
// upload, shows the count counts.
TEST_F(Viewer, PerFrameKeysUploadNothing) {
  auto uploads = [](const std::string& output) {
    std::smatch match;
    EXPECT_TRUE(std::regex_search(output, match, std::regex(R"(view: (\d+) scene uploads)")))
        << output;
    return match.empty() ? -1 : std::stoi(match[1]);
  };
  const std::string perFrameKeys =
      "key B\nframes 1\nkey M\nframes 1\nkey F\nframes 1\nkey F\nframes 1\n"
      "key E\nframes 1\nkey E\nframes 1\nkey W\nkey C\nkey 2\nframes 1\n";
  CommandResult bump = view(perFrameKeys, "bump");
  ASSERT_EQ(bump.exitCode, 0) << bump.output;
  EXPECT_NE(bump.output.find("texture filter: bilinear"), std::string::npos) << bump.output;
  EXPECT_EQ(uploads(bump.output), 1);
  CommandResult env = view(perFrameKeys, "env");
  ASSERT_EQ(env.exitCode, 0) << env.output;
  EXPECT_NE(env.output.find("environment mapping off"), std::string::npos) << env.output;
  EXPECT_EQ(uploads(env.output), 1);
  CommandResult tessellated = view(perFrameKeys + "key T\nframes 1\n", "bump");
  ASSERT_EQ(tessellated.exitCode, 0) << tessellated.output;
  EXPECT_EQ(uploads(tessellated.output), 2);
}

TEST_F(Viewer, TessellationKeysMatchHeadlessRetessellatedScene) {
  CommandResult r = view(
      "key O\nkey T\nframes 2\nscreenshot finer.png\nkey G\nkey G\nframes 2\n"
      "screenshot coarser.png\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (auto [name, scale] : {std::pair{"finer", 2.0f}, std::pair{"coarser", 0.5f}}) {
    Scene scene = builtinScene("default");
    scene.retessellate(scale);
    EXPECT_NE(r.output.find("tessellation x" + std::string(scale == 2.0f ? "2" : "0.5") + ": "),
              std::string::npos)
        << r.output;
    EXPECT_TRUE(matchesImage(headless(scene, ShadingModel::Phong),
                             readImageU8(path(std::string(name) + ".png"))))
        << name;
  }
}

TEST_F(Viewer, StartOptionsMatchHeadlessRenderWithTheSameOptions) {
  CommandResult r =
      view("key O\nframes 2\nscreenshot start.png\n", "teapot --mode gouraud --tess 0.5 --msaa 4");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  Scene scene = builtinScene("teapot");
  scene.retessellate(0.5f);
  RenderSettings settings{kWidth, kHeight, ShadingModel::Gouraud};
  settings.msaaSamples = 4;
  ImageU8 shot = readImageU8(path("start.png"));
  EXPECT_TRUE(matchesImage(render(scene, settings), shot));
  settings.msaaSamples = 1;  // must-fail twin: the same without multisampling
  EXPECT_FALSE(matchesImage(render(scene, settings), shot));
}

TEST_F(Viewer, WireframeDrawsEdgesOverTheShadedImageInEveryDepthMode) {
  // The edges are pulled towards the eye by a depth bias whose sign flips
  // with reversed Z; with the wrong sign the surface hides most of them.
  for (const char* depth : {"d32f", "reversed", "d16"}) {
    CommandResult r =
        view("key O\nframes 2\nscreenshot plain.png\nkey W\nframes 2\nscreenshot wire.png\n",
             std::string("--depth ") + depth);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ImageU8 plain = readImageU8(path("plain.png"));
    ImageU8 wire = readImageU8(path("wire.png"));
    ImageDifference difference = compareImages(plain, wire, 4);
    std::printf("wireframe (%s) changes %.1f%% of pixels\n", depth,
                100.0 * difference.fractionOverThreshold);
    EXPECT_GT(difference.fractionOverThreshold, 0.10) << depth;
    // The background, which has no edges, is untouched.
    EXPECT_EQ(plain.at(2, 2), wire.at(2, 2)) << depth;
  }
}

TEST_F(Viewer, ResizeAndMinimiseRestoreAreValidationClean) {
  CommandResult r = view(
      "frames 3\nresize 400 240\nframes 3\nscreenshot big.png\nminimize\n"
      "frames 5\nrestore\nframes 3\nresize 240 160\nframes 3\n"
      "screenshot small.png\nkey C\nresize 330 170\nframes 3\nquit\n",
      "--validate");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
  ImageU8 big = readImageU8(path("big.png"));
  ImageU8 small = readImageU8(path("small.png"));
  EXPECT_EQ(big.width, 400u);
  EXPECT_EQ(big.height, 240u);
  EXPECT_EQ(small.width, 240u);
  EXPECT_EQ(small.height, 160u);
  // Built at start, after each of three resizes and after the restore.
  std::smatch builds;
  ASSERT_TRUE(std::regex_search(r.output, builds, std::regex(R"(swapchain built (\d+) times)")))
      << r.output;
  EXPECT_GE(std::stoi(builds[1]), 5) << r.output;
}

// Minimised, no frame is drawn to measure against the reference: a
// script's wait-reference there once waited for ever. It now says so and
// goes on (timeout: a regression fails instead of stalling the suite).
TEST_F(Viewer, WaitingForTheReferenceWhileMinimisedEnds) {
  CommandResult r =
      view("key X\nminimize\nwait-reference\nrestore\nframes 1\nquit\n", "", " timeout 60");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("wait-reference: the window is minimised"), std::string::npos)
      << r.output;
}

// Key I blends the impostors' cells: the shot is the headless render with
// --impostors blend, and measured closer to it than to the nearest cell's.
TEST_F(Viewer, ImpostorBlendKeyMatchesHeadlessBlend) {
  std::string scene = std::string(SHADELAB_TEST_DATA_DIR) + "/impostor.json";
  CommandResult r =
      view("key O\nkey I\nframes 3\nscreenshot blend.png\n", scene + " --lod auto --lod-error 100");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("impostors: three cells blended"), std::string::npos) << r.output;
  RenderSettings settings{kWidth, kHeight, ShadingModel::Phong};
  settings.lod = true;
  settings.lodErrorPixels = 100.0f;
  settings.impostorBlend = true;
  RenderResult blended = renderer().renderToImage(loadSceneJson(scene), settings);
  EXPECT_EQ(blended.stats.impostors, 1u);
  settings.impostorBlend = false;
  RenderResult nearest = renderer().renderToImage(loadSceneJson(scene), settings);
  ImageU8 shot = readImageU8(path("blend.png"));
  EXPECT_TRUE(matchesImage(encodeSrgb8(blended.image), shot));
  double toBlend = compareImages(encodeSrgb8(blended.image), shot).rmse;
  double toNearest = compareImages(encodeSrgb8(nearest.image), shot).rmse;
  std::printf("impostor shot: RMSE %.3f to the blend, %.3f to the nearest cell\n", toBlend,
              toNearest);
  EXPECT_LT(2.0 * toBlend, toNearest);
}

// Key P takes the first number whose image and camera sidecar are both
// free: a sidecar left from an earlier screenshot is not written over.
TEST_F(Viewer, ScreenshotKeyWritesOverNoEarlierSidecar) {
  std::ofstream(path("shadelab-screenshot-1.json")) << "mine";
  CommandResult r = view("key O\nframes 2\nkey P\nframes 3\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream kept(path("shadelab-screenshot-1.json"));
  std::string text((std::istreambuf_iterator<char>(kept)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "mine");
  EXPECT_FALSE(fs::exists(path("shadelab-screenshot-1.png"))) << r.output;
  EXPECT_TRUE(fs::exists(path("shadelab-screenshot-2.png"))) << r.output;
  EXPECT_TRUE(fs::exists(path("shadelab-screenshot-2.json"))) << r.output;
}

// Split screen needs a pixel column per view: a window narrower than that
// (3 px, 1x1 as when minimised by a window manager) turns it off with a
// message and the viewer carries on; the teardown is validation clean too.
TEST_F(Viewer, SplitScreenSurvivesAWindowNarrowerThanItsColumns) {
  CommandResult r = view(
      "key C\nframes 3\nresize 3 100\nframes 3\nresize 1 1\nframes 3\nresize 400 200\n"
      "key C\nframes 3\nresize 2 2\nframes 3\nresize 320 180\nframes 3\nscreenshot end.png\n"
      "quit\n",
      "--validate");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("split screen off: the window is narrower than its columns"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(readImageU8(path("end.png")).width, 320u);
}

TEST_F(Viewer, EveryPresentModeRunsValidationClean) {
  for (const char* mode : {"fifo", "mailbox", "immediate"}) {
    std::ofstream(path("script.txt")) << "frames 5\n";
    CommandResult r = run(std::string("view --validate --size 160x90 --present ") + mode +
                          " --script " + path("script.txt"));
    EXPECT_EQ(r.exitCode, 0) << mode << "\n" << r.output;
    EXPECT_NE(r.output.find("view: 5 frames"), std::string::npos) << mode << "\n" << r.output;
    EXPECT_EQ(r.output.find("validation"), std::string::npos) << mode << "\n" << r.output;
  }
}

TEST_F(Viewer, ThousandFramesKeepResidentMemoryFlat) {
#ifdef __SANITIZE_ADDRESS__
  // ASan holds freed blocks in quarantine (up to 256 MB) by design, so RSS
  // grows without a leak (12.6 MB over these frames); that build's
  // LeakSanitizer checks every test for leaks instead.
  GTEST_SKIP() << "resident memory under AddressSanitizer measures its quarantine";
#endif
  CommandResult r = view("frames 100\nmemory\nframes 1000\nmemory\n", "--no-validate");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::regex pattern(R"(VmRSS (\d+) kB after (\d+) frames)");
  std::vector<std::pair<long, long>> samples;
  for (std::sregex_iterator it(r.output.begin(), r.output.end(), pattern), end; it != end; ++it)
    samples.push_back({std::stol((*it)[1]), std::stol((*it)[2])});
  ASSERT_EQ(samples.size(), 2u) << r.output;
  EXPECT_EQ(samples[1].second - samples[0].second, 1000);
  long growth = samples[1].first - samples[0].first;
  std::printf("VmRSS %ld kB at frame %ld, %ld kB at frame %ld: growth %ld kB\n", samples[0].first,
              samples[0].second, samples[1].first, samples[1].second, growth);
  // The heap grows in ~1 MB steps that thin out (0.06-1.1 MB here over
  // frames 100-1100; 3.2 MB over 16,000 frames, flat for the last 8,000);
  // headless `render --frames` grows the same (2.8 MB peak RSS from 100 to
  // 16,100 frames), so it is lavapipe's allocations in the heap kept by
  // main's malloc policy, not a leak. A leak of 4 kB a frame (one staging
  // buffer, one small image, a vector that is never cleared) fails.
  EXPECT_LT(growth, 4096);
}

// Copies shaders/ to the test folder so a test can edit them.
fs::path shaderCopy(const fs::path& dir) {
  fs::path copy = dir / "shaders";
  fs::create_directories(copy);
  for (const auto& entry : fs::directory_iterator(SHADELAB_SHADER_SOURCE_DIR))
    fs::copy_file(entry.path(), copy / entry.path().filename());
  return copy;
}

void replaceInFile(const fs::path& file, const std::string& from, const std::string& to) {
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << file;
  text.replace(at, from.size(), to);
  std::ofstream(file) << text;
}

TEST_F(Viewer, ReloadCompilesShadersFromDisk) {
  fs::path shaders = shaderCopy(dir);
  // The edited shader swaps red and blue: a change that is easy to measure.
  replaceInFile(
      shaders / "forward_fragment.glsl",
      "outColor = vec4(color, environmentEnabled && environmentRefracts ? 1.0 : opacity);",
      "outColor = vec4(color.bgr, environmentEnabled && environmentRefracts ? 1.0 : opacity);");
  CommandResult r =
      view("key O\nframes 2\nscreenshot before.png\nkey R\nframes 2\nscreenshot after.png\n", "",
           "SHADELAB_SHADER_DIR=" + shaders.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("shaders reloaded"), std::string::npos) << r.output;
  ImageU8 before = readImageU8(path("before.png"));
  ImageU8 after = readImageU8(path("after.png"));
  EXPECT_TRUE(matchesImage(headless(builtinScene("default"), ShadingModel::Phong), before));
  EXPECT_FALSE(matchesImage(before, after));
  // A headless renderer given the same edited shaders draws what the window showed.
  std::map<std::string, std::vector<uint32_t>> spirv;
  for (const ShaderVariant& variant : Renderer::shaderVariants()) {
    GlslCompileResult compiled = compileGlsl(shaders, variant);
    ASSERT_TRUE(compiled.ok()) << compiled.log;
    spirv[std::string(variant.name)] = compiled.spirv;
  }
  Renderer edited(context());
  edited.reloadShaders(spirv);
  RenderSettings settings{kWidth, kHeight, ShadingModel::Phong};
  ImageU8 expected = encodeSrgb8(edited.renderToImage(builtinScene("default"), settings).image);
  EXPECT_TRUE(matchesImage(expected, after));
}

TEST_F(Viewer, ShaderCompileErrorIsShownAndLastGoodPipelineKept) {
  fs::path shaders = shaderCopy(dir);
  replaceInFile(
      shaders / "forward_fragment.glsl",
      "outColor = vec4(color, environmentEnabled && environmentRefracts ? 1.0 : opacity);",
      "outColor = colour;");
  CommandResult r = view("key O\nkey R\nframes 2\nscreenshot after.png\n", "",
                         "SHADELAB_SHADER_DIR=" + shaders.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("shader reload failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("forward_fragment.glsl"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'colour' : undeclared identifier"), std::string::npos) << r.output;
  EXPECT_TRUE(matchesImage(headless(builtinScene("default"), ShadingModel::Phong),
                           readImageU8(path("after.png"))));
}

TEST_F(Viewer, OverlayIsDrawnOverTheScene) {
  CommandResult r = view("frames 3\nscreenshot overlay.png\n", "", "", "640x360");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ImageU8 shot = readImageU8(path("overlay.png"));
  RenderSettings settings{640, 360, ShadingModel::Phong};
  ImageU8 scene = render(builtinScene("default"), settings);
  ImageDifference difference = compareImages(scene, shot, 4);
  std::printf("overlay covers %.1f%% of pixels\n", 100.0 * difference.fractionOverThreshold);
  // The status panel covers the top-left; the bottom-right is the scene.
  EXPECT_GT(difference.fractionOverThreshold, 0.03);
  EXPECT_LT(difference.fractionOverThreshold, 0.5);
  EXPECT_EQ(scene.at(630, 350), shot.at(630, 350));
  EXPECT_NE(scene.at(20, 14), shot.at(20, 14));
}

}  // namespace
}  // namespace shadelab::test
