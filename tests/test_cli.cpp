// The shadelab binary as a user runs it: exit codes (0 success, 2 usage and
// input errors), messages that name what was wrong, and no file left behind.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/base/image.h"
#include "run_command.h"

namespace {
namespace fs = std::filesystem;
using shadelab::test::CommandResult;
using shadelab::test::run;
using shadelab::test::runShell;

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "cli" /
          ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  // Files in the test's folder: a failed command must leave none, not even temporaries.
  size_t filesLeft() const {
    return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
  std::string out(const std::string& name) const { return (dir / name).string(); }
  fs::path dir;
};

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23).
std::pair<uint32_t, uint32_t> pngSize(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  unsigned char header[24] = {};
  file.read(reinterpret_cast<char*>(header), 24);
  auto be32 = [&](int at) {
    return uint32_t(header[at]) << 24 | uint32_t(header[at + 1]) << 16 |
           uint32_t(header[at + 2]) << 8 | uint32_t(header[at + 3]);
  };
  if (header[1] != 'P' || header[2] != 'N' || header[3] != 'G') return {0, 0};
  return {be32(16), be32(20)};
}

TEST_F(Cli, RenderWritesPngOfRequestedSize) {
  CommandResult r = run("render -o " + out("a.png") + " --size 96x48");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(out("a.png")), std::make_pair(96u, 48u));
  EXPECT_EQ(filesLeft(), 1u);  // no temporary left beside it
}

// A texture that is a folder: one expectation in the message (there were
// two: "..., expected a regular file (material 'm'), expected an image file").
TEST_F(Cli, TextureOfTheWrongKindSaysWhatWasExpectedOnce) {
  std::filesystem::create_directories(out("t.png"));
  std::ofstream(out("s.json"))
      << R"({"materials": {"m": {"diffuse_map": "t.png"}}, "objects": [{"shape": "plane", "material": "m"}]})";
  CommandResult r = run("render " + out("s.json") + " -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("is a directory, expected an image (material 'm')\n"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("expected an image file"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out("a.png")));
}

TEST_F(Cli, RenderWritesExrWhenAsked) {
  CommandResult r = run("render default -o " + out("a.exr") + " --size 32x32 --mode gouraud");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream file(out("a.exr"), std::ios::binary);
  unsigned char magic[4] = {};
  file.read(reinterpret_cast<char*>(magic), 4);
  EXPECT_EQ(magic[0], 0x76);  // OpenEXR magic 76 2f 31 01
  EXPECT_EQ(magic[1], 0x2f);
}

// Headless output is bit-identical run to run, EXR headers included (they
// once held the time of writing). The runs are over a second apart.
TEST_F(Cli, ExrAndPngAreByteIdenticalRunToRun) {
  for (const char* name : {"a.exr", "a.png"}) {
    std::string first = out(std::string("1") + name), second = out(std::string("2") + name);
    ASSERT_EQ(run("render default -o " + first + " --size 32x32").exitCode, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // another second of the clock
    ASSERT_EQ(run("render default -o " + second + " --size 32x32").exitCode, 0);
    std::ifstream a(first, std::ios::binary), b(second, std::ios::binary);
    std::string bytesA((std::istreambuf_iterator<char>(a)), {});
    std::string bytesB((std::istreambuf_iterator<char>(b)), {});
    EXPECT_FALSE(bytesA.empty()) << name;
    EXPECT_TRUE(bytesA == bytesB) << name << " differs between runs";
  }
}

TEST_F(Cli, TimedRenderPrintsStatistics) {
  CommandResult r = run("render -o " + out("a.png") + " --size 64x64 --frames 12");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("device median"), std::string::npos) << r.output;
}

TEST_F(Cli, UnknownSceneIsAnInputError) {
  CommandResult r = run("render no-such-scene -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("unknown scene 'no-such-scene'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("default"), std::string::npos) << "lists the scenes that exist";
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, MissingSceneFileIsAnInputError) {
  CommandResult r = run("render " + out("nothing.json") + " -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("nothing.json' does not exist"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

// Extensions are read in any case: MODEL.GLB and SCENE.JSON are files.
TEST_F(Cli, SceneFileExtensionsInAnyCase) {
  fs::copy_file(fs::path(SHADELAB_TEST_DATA_DIR) / "triangle.glb", out("MODEL.GLB"));
  std::ofstream(out("SCENE.Json")) << R"({"objects": [{"shape": "sphere"}]})";
  for (const char* scene : {"MODEL.GLB", "SCENE.Json"}) {
    CommandResult r = run("render " + out(scene) + " -o " + out("a.png") + " --size 16x16");
    EXPECT_EQ(r.exitCode, 0) << scene << ": " << r.output;
  }
}

TEST_F(Cli, ZeroSizeIsAnInputError) {
  CommandResult r = run("render -o " + out("a.png") + " --size 0x0");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--size '0x0'"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, MalformedSizeIsAnInputError) {
  CommandResult r = run("render -o " + out("a.png") + " --size abc");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("expected WIDTHxHEIGHT"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, OversizedImageIsAnInputError) {
  CommandResult r = run("render -o " + out("a.png") + " --size 20000x10");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("must be 1.."), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, OutputInMissingFolderIsAnInputError) {
  CommandResult r = run("render -o " + out("missing/a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, UnsupportedOutputExtensionIsAnInputError) {
  CommandResult r = run("render -o " + out("a.bmpx"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("expected .png or .exr"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, UnknownModeIsAnInputError) {
  CommandResult r = run("render -o " + out("a.png") + " --mode toon");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--mode 'toon'"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, UnknownOptionIsAUsageError) {
  CommandResult r = run("render -o " + out("a.png") + " --shiny");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--shiny"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, MissingOutputIsAUsageError) {
  CommandResult r = run("render");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--output"), std::string::npos) << r.output;
}

TEST_F(Cli, UnknownDeviceIsAnInputError) {
  CommandResult r = run("info --device NoSuchGpu");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("NoSuchGpu"), std::string::npos) << r.output;
}

TEST_F(Cli, InfoNamesDeviceDriverAndVersion) {
  CommandResult r = run("info");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("device:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("driver:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("vulkan:          1.3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("depth modes:     d16 d24 d32f reversed\n"), std::string::npos)
      << "lavapipe renders to every depth format\n"
      << r.output;
}

TEST_F(Cli, HelpSucceedsForEachCommand) {
  for (const char* command : {"--help", "render --help", "compare --help", "bench --help",
                              "info --help", "trace --help", "view --help", "scenes --help"}) {
    CommandResult r = run(command);
    EXPECT_EQ(r.exitCode, 0) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("Usage"), std::string::npos) << command;
  }
}

TEST_F(Cli, VersionPrintsTheProjectVersion) {
  CommandResult r = run("--version");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output, "shadelab " SHADELAB_VERSION "\n");
}

std::string readText(const std::string& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST_F(Cli, ScenesListsEachBuiltInWithItsDescription) {
  CommandResult r = run("scenes");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string lines = "\n" + r.output;
  for (const char* name : {"bump", "default", "dense", "env", "highlight", "lod", "mip-plane",
                           "shadows", "spheres", "teapot", "trees", "whitted", "zfight"})
    EXPECT_NE(lines.find(std::string("\n") + name + " "), std::string::npos) << name;
  EXPECT_NE(r.output.find("teapot     The Utah teapot"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 13) << "one line each, no more";
}

// The copy a user makes renders exactly as the built-in it came from.
TEST_F(Cli, ScenesPrintWritesTheFileThatRendersLikeTheBuiltIn) {
  for (std::string name : {"default", "bump"}) {
    std::string copy = out(name + "-copy.json");
    CommandResult printed = run("scenes --print " + name + " > " + copy);
    ASSERT_EQ(printed.exitCode, 0) << readText(copy);
    std::string asset = std::string(SHADELAB_ASSET_DIR) + "/scenes/" + name + ".json";
    EXPECT_EQ(readText(copy), readText(asset)) << "the file in assets/scenes, byte for byte";
    for (const auto& [scene, png] :
         {std::pair{name, name + "-builtin.png"}, std::pair{copy, name + "-copy.png"}}) {
      CommandResult r = run("render " + scene + " --size 160x90 -o " + out(png));
      ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    shadelab::ImageU8 builtIn = shadelab::readImageU8(out(name + "-builtin.png"));
    shadelab::ImageU8 fromCopy = shadelab::readImageU8(out(name + "-copy.png"));
    EXPECT_EQ(fromCopy.width, 160u);
    EXPECT_TRUE(fromCopy.pixels == builtIn.pixels) << name << ": the copy renders differently";
  }
}

TEST_F(Cli, ScenesPrintUnknownNameIsAnInputError) {
  CommandResult r = run("scenes --print no-such-scene");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("unknown built-in scene 'no-such-scene'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bump, default, dense"), std::string::npos) << "lists the names";
  EXPECT_EQ(r.output.find('{'), std::string::npos) << "no JSON printed";
}

// --eye/--at/--up/--fovy draw exactly what a scene file with that camera draws.
TEST_F(Cli, CameraOptionsRenderLikeTheSameCameraInTheSceneFile) {
  std::string text = readText(std::string(SHADELAB_ASSET_DIR) + "/scenes/default.json");
  std::string camera =
      R"("camera": {"eye": [2.5, 4, 6], "at": [0, 0.5, -0.25], "up": [0.1, 1, 0], "fovy": 30})";
  text = std::regex_replace(text, std::regex(R"("camera": \{[^}]*\})"), camera);
  ASSERT_NE(text.find(camera), std::string::npos);
  std::ofstream(out("camera.json")) << text;
  for (const auto& [arguments, png] :
       {std::pair<std::string, std::string>{out("camera.json"), "file.png"},
        {"default --eye 2.5,4,6 --at 0,0.5,-0.25 --up 0.1,1,0 --fovy 30", "options.png"},
        {"default", "scene.png"},
        {"default --eye 2.5,4,6 --at 0,0.5,-0.25 --up 0.1,1,0 --fovy 30 --ortho", "ortho.png"}}) {
    CommandResult r = run("render " + arguments + " --size 160x90 -o " + out(png));
    ASSERT_EQ(r.exitCode, 0) << arguments << "\n" << r.output;
  }
  shadelab::ImageU8 file = shadelab::readImageU8(out("file.png"));
  EXPECT_TRUE(shadelab::readImageU8(out("options.png")).pixels == file.pixels);
  EXPECT_FALSE(shadelab::readImageU8(out("scene.png")).pixels == file.pixels) << "options moved it";
  EXPECT_FALSE(shadelab::readImageU8(out("ortho.png")).pixels == file.pixels)
      << "--ortho changed it";
}

TEST_F(Cli, BadCameraOptionsNameTheOption) {
  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {"--eye 1,2", "--eye '1,2': expected three finite numbers X,Y,Z"},
           {"--at 0,0,nan", "--at '0,0,nan': expected three finite numbers X,Y,Z"},
           {"--eye 0,1,2 --at 0,1,2", "--at: at equals eye, so there is no viewing direction"},
           {"--up 0,0,0", "--up: zero-length up vector"},
           {"--eye 0,5,0 --at 0,0,0", "--up: up is parallel to the viewing direction"},
           {"--fovy 180", "--fovy 180: expected degrees greater than 0 and less than 180"},
           {out("ortho.json") + " --fovy 30",
            "--fovy: the scene's camera is not a perspective camera"}}) {
    std::ofstream(out("ortho.json")) << R"({"camera": {"projection": "orthographic"}, "objects": [
        {"shape": "sphere", "material": {"kd": [1, 1, 1]}}]})";
    std::string scene = arguments.rfind(out("ortho.json"), 0) == 0 ? "" : "default ";
    CommandResult r = run("render " + scene + arguments + " -o " + out("camera-bad.png"));
    EXPECT_EQ(r.exitCode, 2) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << arguments << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(out("camera-bad.png"))) << arguments;
  }
}

TEST_F(Cli, TraceBouncesIsNotRendersDepth) {
  CommandResult r = run("trace spheres --bounces 0 --spp 1 --size 32x18 -o " + out("t.png"));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("1 spp, 0 bounces"), std::string::npos) << r.output;
  CommandResult old = run("trace spheres --depth 3 --size 32x18 -o " + out("t2.png"));
  EXPECT_EQ(old.exitCode, 2) << "trace's --depth is now --bounces\n" << old.output;
  EXPECT_FALSE(std::filesystem::exists(out("t2.png")));
}

TEST_F(Cli, ScenesWithoutLightsOrWithMirrorsAndNoEnvironmentWarn) {
  std::ofstream(out("dark.json")) << R"({"objects": [{"shape": "sphere"}]})";
  std::ofstream(out("mirror.json"))
      << R"({"lights": [{"type": "point", "position": [0, 3, 3]}], "objects": [
        {"name": "ball", "shape": "sphere", "material": {"reflectivity": 0.9}}]})";
  CommandResult dark = run("render " + out("dark.json") + " --size 32x18 -o " + out("d.png"));
  EXPECT_EQ(dark.exitCode, 0) << dark.output;
  EXPECT_NE(dark.output.find("shadelab: warning: scene 'dark' has no lights"), std::string::npos)
      << dark.output;
  CommandResult mirror = run("render " + out("mirror.json") + " --size 32x18 -o " + out("m.png"));
  EXPECT_EQ(mirror.exitCode, 0) << mirror.output;
  EXPECT_NE(mirror.output.find("1 reflective or transparent object(s) (first: 'ball') in a scene "
                               "without an environment"),
            std::string::npos)
      << mirror.output;
  CommandResult lit = run("render default --size 32x18 -o " + out("l.png"));
  EXPECT_EQ(lit.output.find("warning"), std::string::npos) << lit.output;
}

// A near plane the depth buffer cannot resolve draws a blank or broken image;
// render says so before drawing (depthPrecisionWarning), and not where the
// depth buffer is fine.
TEST_F(Cli, NearPlaneTheDepthBufferCannotResolveWarns) {
  std::ofstream(out("near.json"))
      << R"({"camera": {"eye": [0, 2, 6], "at": [0, 0, 0], "near": 1e-7, "far": 100},
        "lights": [{"type": "point", "position": [0, 3, 3]}],
        "objects": [{"shape": "sphere"}]})";
  CommandResult blank = run("render " + out("near.json") + " --size 32x18 -o " + out("n.png"));
  EXPECT_EQ(blank.exitCode, 0) << blank.output;
  EXPECT_NE(blank.output.find("shadelab: warning: depth mode d32f with near 1e-07 and far 100: at "
                              "the camera's target, 6.32 away, depth rounds to the far plane's "
                              "and surfaces are not drawn"),
            std::string::npos)
      << blank.output;
  CommandResult reversed =
      run("render " + out("near.json") + " --depth reversed --size 32x18 -o " + out("r.png"));
  EXPECT_EQ(reversed.output.find("warning"), std::string::npos) << reversed.output;
  CommandResult fights = run("render zfight --depth d16 --size 32x18 -o " + out("z.png"));
  EXPECT_NE(fights.output.find("depths less than 2.08 (1.78% of the distance) apart are not told "
                               "apart"),
            std::string::npos)
      << fights.output;
  CommandResult fine = run("render default --depth d16 --size 32x18 -o " + out("d.png"));
  EXPECT_EQ(fine.output.find("warning"), std::string::npos) << fine.output;
  // compare warns once per depth mode its columns use.
  CommandResult columns =
      run("compare zfight --size 32x18 --column depth=d16 --column name=again,depth=d16 "
          "--column depth=reversed -o " +
          out("z.png"));
  EXPECT_EQ(columns.exitCode, 0) << columns.output;
  size_t first = columns.output.find("depth mode d16 with near 0.1");
  EXPECT_NE(first, std::string::npos) << columns.output;
  EXPECT_EQ(columns.output.find("depth mode d16", first + 1), std::string::npos) << columns.output;
  EXPECT_EQ(columns.output.find("depth mode reversed"), std::string::npos) << columns.output;
}

TEST_F(Cli, RenderLoadsJsonSceneFile) {
  CommandResult r = run(std::string("render ") + SHADELAB_ASSET_DIR +
                        "/scenes/three-spheres.json -o " + out("a.png") + " --size 64x36");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(out("a.png")), std::make_pair(64u, 36u));
}

TEST_F(Cli, MalformedJsonSceneNamesFileAndField) {
  std::ofstream(out("bad.json"))
      << R"({"camera": {"eye": [0, 1], "at": [0, 0, 0]}, "objects": []})";
  CommandResult r = run("render " + out("bad.json") + " -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("camera.eye"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 1u);  // only the scene file itself
}

TEST_F(Cli, MissingPanoramaNamesFieldAndFileAndWritesNothing) {
  std::ofstream(out("scene.json"))
      << R"({"environment": {"type": "equirect", "file": "gone.hdr"}, "objects": []})";
  CommandResult r = run("render " + out("scene.json") + " -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("environment.file: image '" + out("gone.hdr") + "' does not exist"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(filesLeft(), 1u);  // only the scene file: no image, no temporary
}

TEST_F(Cli, EnvOnAndOffRenderTheStudioScene) {
  std::string scene = std::string(SHADELAB_ASSET_DIR) + "/scenes/studio.json";
  CommandResult on = run("render " + scene + " -o " + out("on.png") + " --size 64x36 --env on");
  ASSERT_EQ(on.exitCode, 0) << on.output;
  CommandResult off = run("render " + scene + " -o " + out("off.png") + " --size 64x36 --env off");
  ASSERT_EQ(off.exitCode, 0) << off.output;
  EXPECT_NE(readText(out("on.png")), readText(out("off.png")));
}

// Every on/off switch of every command reads the same name table: one
// message, one exit code.
TEST_F(Cli, BadSwitchValuesGetOneMessage) {
  for (std::string command :
       {"render env -o " + out("a.png") + " --env maybe",
        "render bump -o " + out("a.png") + " --bump maybe",
        "trace -o " + out("a.png") + " --size 8x8 --shadows maybe",
        "trace -o " + out("a.png") + " --size 8x8 --fresnel maybe",
        "compare -o " + out("a.png") + " --size 8x8 --reference-shadows maybe"}) {
    CommandResult r = run(command);
    EXPECT_EQ(r.exitCode, 2) << command << "\n" << r.output;
    std::string option = command.substr(command.rfind(" --") + 1);
    option = option.substr(0, option.find(' '));
    EXPECT_NE(r.output.find(option + " 'maybe': expected one of on, off"), std::string::npos)
        << command << "\n"
        << r.output;
    EXPECT_EQ(filesLeft(), 0u) << command;
  }
}

// Bad shadow options: exit 2, a message naming the option and the allowed
// range, no image. 20000 is above lavapipe's 16384 (checked by the renderer).
TEST_F(Cli, BadShadowOptionsNameTheOptionAndRange) {
  struct Case {
    std::string arguments, expected;
  };
  for (const Case& c :
       {Case{"--shadows soft", "--shadows 'soft': expected one of off, hard, pcf3, pcf5"},
        Case{"--shadow-size 0", "--shadow-size 0: expected a map size from 1"},
        Case{"--shadow-size -8", "--shadow-size -8: expected a map size from 1"},
        Case{"--shadow-size 20000", "--shadow-size 20000: expected 1..16384"},
        Case{"--shadow-bias -1", "--shadow-bias -1: expected 0 to 64 texels"},
        Case{"--shadow-slope-bias 65", "--shadow-slope-bias 65: expected 0 to 64 texels"},
        Case{"--shadow-normal-offset -0.5", "--shadow-normal-offset -0.5: expected 0 to 64"}}) {
    CommandResult r = run("render shadows --size 16x16 -o " + out("a.png") + " " + c.arguments);
    EXPECT_EQ(r.exitCode, 2) << c.arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.arguments << "\n" << r.output;
    EXPECT_EQ(filesLeft(), 0u) << c.arguments;
  }
}

// A scene file's shadow fields are checked like every other field.
TEST_F(Cli, BadShadowFieldsInASceneFile) {
  std::string scene = out("bad-shadows.json");
  std::ofstream(scene)
      << R"({"lights": [{"type": "directional", "direction": [0, -1, 0], "shadows": "yes"}],)"
      << R"( "objects": []})";
  CommandResult r = run("render " + scene + " --size 16x16 -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("lights[0].shadows: expected true or false"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out("a.png")));
}

TEST_F(Cli, TraceEpsilonIsValidated) {
  for (std::string value : {"-1", "2", "nan", "inf", "abc", "1e-4x"}) {
    CommandResult r = run("trace -o " + out("a.png") + " --size 8x8 --epsilon " + value);
    EXPECT_EQ(r.exitCode, 2) << value << "\n" << r.output;
    EXPECT_NE(r.output.find("expected a number from 0 to 1"), std::string::npos) << value << "\n"
                                                                                 << r.output;
    EXPECT_EQ(filesLeft(), 0u) << value;
  }
  // Epsilon 0 brings shadow acne back: the image differs from the default's.
  ASSERT_EQ(run("trace whitted -o " + out("e0.png") + " --size 32x18 --spp 1 --epsilon 0").exitCode,
            0);
  // Below a float's smallest (from_chars into a float called it out of range): 0 as well.
  ASSERT_EQ(
      run("trace whitted -o " + out("tiny.png") + " --size 32x18 --spp 1 --epsilon 1e-50").exitCode,
      0);
  EXPECT_EQ(readText(out("tiny.png")), readText(out("e0.png")));
  ASSERT_EQ(run("trace whitted -o " + out("e.png") + " --size 32x18 --spp 1").exitCode, 0);
  EXPECT_NE(readText(out("e0.png")), readText(out("e.png")));
}

TEST_F(Cli, TessellationOutOfRangeIsAUsageError) {
  CommandResult r = run("render -o " + out("a.png") + " --tess 0");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--tess"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, CompareWritesSheetAndNumbers) {
  CommandResult r =
      run("compare teapot -o " + out("sheet.png") + " --size 64x36 --modes flat,phong");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // Reference, flat and phong across; images above heatmaps and labels.
  auto [width, height] = pngSize(out("sheet.png"));
  EXPECT_GE(width, 3u * 64u);
  EXPECT_GE(height, 2u * 36u);
  std::string json = readText(out("sheet.json"));
  for (const char* key : {"\"flat\"", "\"phong\"", "\"rmse\"", "\"psnr\"", "\"ssim\"", "\"flip\"",
                          "Whitted ray tracer, 4 spp"})
    EXPECT_NE(json.find(key), std::string::npos) << key << " in " << json;
  EXPECT_EQ(filesLeft(), 2u);
}

TEST_F(Cli, CompareKeepsTheRasterReference) {
  CommandResult r =
      run("compare -o " + out("sheet.png") + " --size 64x36 --modes phong --reference raster");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(readText(out("sheet.json")).find("4x MSAA"), std::string::npos);
}

// The triangle budget counts the raster reference's 4x only when it is
// drawn: the traced reference traces the scene as loaded. Between the default
// scene's 4,972 triangles at 1x and 80,524 at 4x, the traced compare runs and
// the raster one is refused, naming its reference. (Before, both were refused,
// and `compare lod` could not run at the default budget.)
TEST_F(Cli, CompareBudgetsTheRasterReferenceOnlyWhenItIsDrawn) {
  std::string budget = " --size 32x18 --modes phong --max-triangles 20000";
  CommandResult traced = run("compare -o " + out("traced.png") + budget);
  EXPECT_EQ(traced.exitCode, 0) << traced.output;
  CommandResult raster = run("compare -o " + out("raster.png") + budget + " --reference raster");
  EXPECT_EQ(raster.exitCode, 2) << raster.output;
  EXPECT_NE(raster.output.find("(its raster reference is 4x, its columns' tess up to 1.000x): "
                               "an estimated 80524 triangles"),
            std::string::npos)
      << raster.output;
  EXPECT_FALSE(std::filesystem::exists(out("raster.png")));
}

// On a scene with an environment the sheet gains the traced reflection
// regions and each mode's FLIP split by them; a third row makes it taller.
TEST_F(Cli, CompareSplitsEnvironmentMappingErrorByReflectionRegion) {
  CommandResult r = run("compare env -o " + out("sheet.png") + " --size 96x54 --modes phong");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_GE(pngSize(out("sheet.png")).second, 3u * 54u);
  const nlohmann::json report = nlohmann::json::parse(readText(out("sheet.json")));
  EXPECT_GT(report["reflectionRegions"]["hitsObjectPixels"].get<int>(), 50);
  EXPECT_GT(report["reflectionRegions"]["escapesPixels"].get<int>(), 50);
  const nlohmann::json& phong = report["modes"][0];
  EXPECT_GT(phong["flipHitsObject"].get<double>(), phong["flipEscapes"].get<double>());
  EXPECT_NE(r.output.find("FLIP where the reflection hits an object"), std::string::npos)
      << r.output;
}

// compare's columns in a suite of their own: ctest runs it beside Cli, whose
// one process is already long on a loaded 2-core machine.
class CompareColumns : public Cli {};

// --column with --against: a column drawn with the baseline's very settings
// measures zero (drawing is deterministic), and the comparison is not blind:
// a coarser column of the same model measures clearly above it.
TEST_F(CompareColumns, MeasureAgainstANamedColumn) {
  CommandResult r =
      run("compare -o " + out("sheet.png") +
          " --size 96x54 --column name=base,phong,tess=2,msaa=4"
          " --column name=same,phong,tess=2,msaa=4 --column name=coarse,phong,tess=0.5"
          " --against base");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const nlohmann::json report = nlohmann::json::parse(readText(out("sheet.json")));
  EXPECT_EQ(report["against"], "base");
  ASSERT_EQ(report["columns"].size(), 3u);
  const nlohmann::json& same = report["columns"][1]["metrics"];
  const nlohmann::json& coarse = report["columns"][2]["metrics"];
  EXPECT_EQ(same["rmse"].get<double>(), 0.0);
  EXPECT_EQ(same["flip"].get<double>(), 0.0);
  EXPECT_GT(coarse["flip"].get<double>(), 0.005);  // measured 0.018 at 240x135
  EXPECT_GT(coarse["rmse"].get<double>(), 1.0);
  EXPECT_FALSE(report["columns"][0].contains("metrics"));  // the baseline itself
  EXPECT_NE(r.output.find("against: column 'base'"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 2u);
}

// A column whose settings differ from the others' in more than the model is
// drawn alone at the cell's size; drawn alone, a Phong column measures
// against the trace as the same column of a --modes split frame does (one
// camera, one projection; the shadow map's fit to the frame may move a
// texel, hence a tolerance of 1e-4 in FLIP, 0.05 in RMSE).
TEST_F(CompareColumns, DrawnAloneMeasuresAsInTheSplitFrame) {
  CommandResult split =
      run("compare -o " + out("split.png") + " --size 96x54 --spp 1 --modes flat,phong");
  ASSERT_EQ(split.exitCode, 0) << split.output;
  CommandResult alone = run("compare -o " + out("alone.png") +
                            " --size 96x54 --spp 1 --column phong --column gouraud,tess=4");
  ASSERT_EQ(alone.exitCode, 0) << alone.output;
  const nlohmann::json modes = nlohmann::json::parse(readText(out("split.json")))["modes"];
  const nlohmann::json columns = nlohmann::json::parse(readText(out("alone.json")))["columns"];
  const nlohmann::json& fromSplit = modes[1];
  const nlohmann::json& drawnAlone = columns[0]["metrics"];
  EXPECT_NEAR(drawnAlone["flip"].get<double>(), fromSplit["flip"].get<double>(), 1e-4);
  EXPECT_NEAR(drawnAlone["rmse"].get<double>(), fromSplit["rmse"].get<double>(), 0.05);
  // And not blindly: the flat column of the split frame is well apart.
  EXPECT_GT(std::abs(modes[0]["flip"].get<double>() - drawnAlone["flip"].get<double>()), 1e-3);
  EXPECT_EQ(columns[1]["settings"]["tess"], 4.0);
}

TEST_F(Cli, CompareUnknownReferenceIsAnInputError) {
  CommandResult r = run("compare -o " + out("sheet.png") + " --reference photo");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("photo"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, TraceWritesTheImageAndReportsRays) {
  CommandResult r = run("trace whitted -o " + out("ref.png") + " --size 48x27 --spp 4 --threads 2");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(out("ref.png")), std::make_pair(48u, 27u));
  EXPECT_NE(r.output.find("Mrays/s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("5184 primary"), std::string::npos) << r.output;  // 48 * 27 * 4
  EXPECT_EQ(filesLeft(), 1u);
}

TEST_F(Cli, TraceNonSquareSampleCountIsAnInputError) {
  CommandResult r = run("trace -o " + out("ref.png") + " --spp 8");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--spp 8: expected a square number n*n from 1 to 256"), std::string::npos)
      << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, CompareUnknownModeIsAnInputError) {
  CommandResult r = run("compare -o " + out("sheet.png") + " --modes flat,shiny");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("shiny"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, BenchWritesOneCsvRowPerSetting) {
  CommandResult r = run("bench spheres -o " + out("bench") +
                        " --size 64x36 --frames 4 --rounds 2 --modes unlit,phong --tess 0.5,1 "
                        "--msaa 1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string csv = readText(out("bench/results.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 2) << csv;
  EXPECT_EQ(csv.rfind("scene,width,height,mode,tessellation,msaa,filter,shadows,shadow_size,"
                      "triangles,frames,",
                      0),
            0u)
      << csv;
  // 2 rounds x (4 frames - 1 warm-up) steady frames per setting.
  EXPECT_NE(csv.find("spheres,64,36,phong,0.5,1,material,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",6,"), std::string::npos) << csv;
  EXPECT_NE(r.output.find("x floor"), std::string::npos) << r.output;
}

// A bench killed while it measures leaves nothing: its folder is made only
// with the results. (--frames 100000 keeps it measuring well past the kill:
// 2000 frames of 32x18 took ~2 s once steady frames stopped flushing.)
TEST_F(Cli, KilledBenchLeavesNoFolder) {
  CommandResult r = run("bench -o " + out("b") +
                        " --size 32x18 --frames 100000 --modes unlit --tess 1 --msaa 1 "
                        "--reference raster & pid=$!; sleep 2; kill -TERM $pid; wait $pid");
  EXPECT_EQ(r.exitCode, 128 + 15) << r.output;  // ended by SIGTERM, as the shell reports it
  EXPECT_FALSE(fs::exists(out("b")));
  EXPECT_EQ(filesLeft(), 0u);
}

// A frame sequence stages each frame as it is drawn and puts them in place
// only at the end: terminated part-way, it leaves none of them, staged or
// not. The shell waits until a staged frame exists before the signal.
TEST_F(Cli, TerminatedSequenceLeavesNoStagedFrames) {
  CommandResult r = run("render default --turntable 400 --size 320x180 -o " + out("t.png") +
                        " & pid=$!; for i in $(seq 3000); do ls -A " + dir.string() +
                        " | grep -q staged && break; sleep 0.01; done; ls -A " + dir.string() +
                        " | grep -q staged && echo STAGED-SEEN; kill -TERM $pid; wait $pid");
  EXPECT_NE(r.output.find("STAGED-SEEN"), std::string::npos) << r.output;
  EXPECT_EQ(r.exitCode, 128 + 15) << "the sequence ended before the signal\n" << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, MissingTextureNamesTheFileAndTheMaterialAndWritesNothing) {
  std::ofstream(out("textured.json"))
      << R"({"materials": {"brick": {"diffuse_map": "maps/missing.png"}},
             "objects": [{"shape": "plane", "material": "brick"}]})";
  CommandResult r = run("render " + out("textured.json") + " -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("maps/missing.png"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("material 'brick'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("materials.brick.diffuse_map"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 1u);  // only the scene file itself
}

TEST_F(Cli, UnreadableTextureIsAnInputError) {
  std::ofstream(out("noise.png")) << "not a png";
  std::ofstream(out("textured.json")) << R"({"objects": [{"name": "ball", "shape": "sphere",
                          "material": {"normal_map": "noise.png"}}]})";
  CommandResult r = run("render " + out("textured.json") + " -o " + out("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("noise.png"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the material of object 'ball'"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 2u);
}

TEST_F(Cli, TextureOptionsRenderAndBadValuesAreInputErrors) {
  CommandResult r = run("render mip-plane -o " + out("a.png") +
                        " --size 64x36 --filter nearest --bump off --mip-tint");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(out("a.png")), std::make_pair(64u, 36u));
  for (const char* bad : {"--filter cubic", "--bump maybe"}) {
    CommandResult e = run("render bump -o " + out("b.png") + " " + bad);
    EXPECT_EQ(e.exitCode, 2) << bad << ": " << e.output;
    EXPECT_NE(e.output.find(std::string(bad).substr(0, 6)), std::string::npos) << e.output;
  }
  EXPECT_EQ(filesLeft(), 1u);
}

TEST_F(Cli, BenchBadSampleCountIsAUsageError) {
  CommandResult r = run("bench -o " + out("bench") + " --msaa 1,3");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--msaa"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

// Each broken glTF file of tests/data/bad: exit 2, a message naming the file
// and the defect, and no output image (not even a temporary).
TEST_F(Cli, BrokenGltfFilesAreInputErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"truncated.glb", "invalid GLB: truncated"},
      {"syntax_error.gltf", "parse error at line 73"},
      {"accessor_past_buffer.gltf", "past the end of its bufferView"},
      {"accessor_count_overflow.gltf", "more than 2^64 bytes"},
      {"bufferview_offset_overflow.gltf", "runs past the end of its buffer"},
      {"missing_buffer.gltf", "does_not_exist.bin"},
      {"missing_image.gltf", "no_such_image.png"},
      {"required_extension.gltf", "KHR_draco_mesh_compression"},
      {"zero_triangles.gltf", "no triangles"},
      {"index_out_of_range.gltf", "out of range"},
  };
  for (const auto& [file, problem] : cases) {
    std::string path = std::string(SHADELAB_TEST_DATA_DIR) + "/bad/" + file;
    CommandResult r = run("render " + path + " -o " + out("a.png") + " --size 32x32");
    EXPECT_EQ(r.exitCode, 2) << file << ": " << r.output;
    EXPECT_NE(r.output.find("error: " + path + ": "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(problem), std::string::npos) << r.output;
    EXPECT_EQ(filesLeft(), 0u) << file;
  }
}

TEST_F(Cli, RendersAGltfWithSimplificationAndAutoTessellation) {
  CommandResult gltf = run("render " + std::string(SHADELAB_TEST_DATA_DIR) + "/textured.gltf -o " +
                           out("a.png") + " --size 64x48 --simplify 1");
  ASSERT_EQ(gltf.exitCode, 0) << gltf.output;
  EXPECT_NE(gltf.output.find("simplified loaded meshes to 1 px: 2 -> 2 triangles"),
            std::string::npos)
      << gltf.output;
  EXPECT_EQ(pngSize(out("a.png")), std::make_pair(64u, 48u));
  CommandResult automatic = run("render spheres -o " + out("b.png") + " --size 64x36 --tess auto");
  ASSERT_EQ(automatic.exitCode, 0) << automatic.output;
  CommandResult bad = run("render spheres -o " + out("c.png") + " --tess sometimes");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("--tess 'sometimes': expected a factor from 0.125 to 16, or auto"),
            std::string::npos)
      << bad.output;
  EXPECT_EQ(filesLeft(), 2u);
}

TEST_F(Cli, BadDepthValueIsAnInputError) {
  CommandResult r = run("render -o " + out("a.png") + " --depth d8");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--depth 'd8': expected one of d16, d24, d32f, reversed"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, RenderWithEachDepthMode) {
  for (const char* depth : {"d16", "d24", "d32f", "reversed"}) {
    std::string name = std::string(depth) + ".png";
    CommandResult r = run("render zfight -o " + out(name) + " --size 48x27 --depth " + depth);
    ASSERT_EQ(r.exitCode, 0) << depth << "\n" << r.output;
    EXPECT_EQ(pngSize(out(name)), std::make_pair(48u, 27u)) << depth;
  }
}

// Splits CSV text into rows of cells (no quoting: bench output has none).
std::vector<std::vector<std::string>> csvRows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    rows.emplace_back();
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) rows.back().push_back(cell);
    if (!line.empty() && line.back() == ',') rows.back().emplace_back();
  }
  return rows;
}

// Runs `bench ARGUMENTS -o FOLDER` and returns the rows of its results.csv;
// a failed run is a test failure and gives no rows.
std::vector<std::vector<std::string>> benchRows(const std::string& arguments,
                                                const std::string& folder) {
  CommandResult r = run("bench " + arguments + " -o " + folder);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  if (r.exitCode != 0) return {};
  return csvRows(readText(folder + "/results.csv"));
}

// The share of the `zfight` planes' pixels in a PNG where the farther
// (blue) plane shows.
double farPlaneShare(const std::string& png) {
  shadelab::ImageU8 image = shadelab::readImageU8(png);
  size_t blue = 0, covered = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      glm::u8vec4 p = image.at(x, y);
      if (p.r + p.b < 128) continue;  // background
      ++covered;
      blue += p.b > p.r;
    }
  EXPECT_GT(covered, image.width * image.height / 4) << png;
  return double(blue) / double(std::max<size_t>(covered, 1));
}

// Sorted, the nearer (red) plane of `zfight` is drawn first and wins every
// depth tie, so D16's z-fighting does not show; `--draw-order scene` draws
// the farther (blue) plane first, as the scene lists it, and it shows.
TEST_F(Cli, DrawOrderSceneShowsZFighting) {
  auto farShare = [&](const std::string& options) {
    std::string png = out("z.png");
    CommandResult r = run("render zfight --size 96x54 -o " + png + " " + options);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return farPlaneShare(png);
  };
  EXPECT_GT(farShare("--depth d16 --draw-order scene"), 0.5);
  EXPECT_LT(farShare("--depth d16"), 0.01);
  EXPECT_LT(farShare("--depth reversed --draw-order scene"), 0.01);
  CommandResult bad = run("render zfight -o " + out("z.png") + " --draw-order random");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
}

// The device memory a render reports holds its targets: 4x MSAA's are larger.
TEST_F(Cli, DeviceMemoryIncludesTheRenderTargets) {
  auto memory = [&](const std::string& msaa) {
    CommandResult r =
        run("render --json --shadows off --size 320x180 --msaa " + msaa + " -o " + out("m.png"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::smatch match;
    EXPECT_TRUE(std::regex_search(r.output, match, std::regex("\"device_memory_bytes\":([0-9]+)")))
        << r.output;
    return match.empty() ? 0.0 : std::stod(match[1]);
  };
  // 320x180: an RGBA16F 4x target and its resolve are ~2.3 MB more per frame in flight.
  EXPECT_GT(memory("4") - memory("1"), 2.0e6);
  // In one process, a setting without shadows after one with 2048-texel maps
  // holds no maps (it reported the previous row's 114 MB).
  auto rows = benchRows(
      "default --size 64x36 --frames 2 --rounds 1 --modes phong --tess 1 --msaa 1 "
      "--shadows hard,off --shadow-sizes 2048 --reference none",
      out("bm"));
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(rows[0][15], "device_memory_mb");
  ASSERT_EQ(rows[1][7], "hard");
  ASSERT_EQ(rows[2][7], "off");
  EXPECT_GT(std::stod(rows[1][15]), 50.0) << "seven 2048-texel D32 layers";
  EXPECT_LT(std::stod(rows[2][15]), 10.0);
}

// A chart decodes as a PNG, is mostly white paper, and has ink, grid and
// series colours on it: more than a blank or single-colour image.
void expectDrawnChart(const std::string& path) {
  shadelab::ImageU8 image = shadelab::readImageU8(path);
  size_t white = 0;
  std::vector<uint32_t> colours;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      glm::u8vec4 p = image.at(x, y);
      white += p == glm::u8vec4(255);
      uint32_t packed = uint32_t(p.r) << 16 | uint32_t(p.g) << 8 | p.b;
      if (colours.size() < 64 && std::find(colours.begin(), colours.end(), packed) == colours.end())
        colours.push_back(packed);
    }
  double paper = double(white) / (double(image.width) * image.height);
  EXPECT_GT(paper, 0.5) << path;
  EXPECT_LT(paper, 0.99) << path;
  EXPECT_GT(colours.size(), 8u) << path;
}

TEST_F(Cli, StudyZfightWritesTablesCsvsChartsAndImages) {
  CommandResult r = run("study zfight -o " + out("z") + " --size 160x90");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* sweep : {"near", "distance"}) {
    std::string csv = out("z/zfight_" + std::string(sweep) + ".csv");
    auto rows = csvRows(readText(csv));
    ASSERT_EQ(rows.size(), 1u + 2 * 4 * 5) << "header + projections x depth modes x 5 values";
    EXPECT_EQ(rows[0], (std::vector<std::string>{
                           "projection", "depth", "format", "near", "far", "distance", "gap",
                           "width", "height", "covered_pixels", "wrong_pixels", "wrong_fraction"}));
    EXPECT_EQ(rows[1][0], "perspective");
    EXPECT_EQ(rows[1][1], "d16");
    EXPECT_EQ(rows[1][2], "D16_UNORM");
    EXPECT_EQ(rows[40][0], "orthographic");
    EXPECT_EQ(rows[40][1], "reversed");
    std::string chart = out("z/zfight_" + std::string(sweep) + ".png");
    auto [width, height] = pngSize(chart);
    EXPECT_GT(width, 1000u);
    EXPECT_GT(height, 300u);
    expectDrawnChart(chart);
  }
  EXPECT_EQ(pngSize(out("z/d16_perspective_distance29.png")), std::make_pair(160u, 90u));
  // The images show what the table counts: D16 far away loses most of the
  // nearer plane, close by none of it (drawn sorted, they showed none).
  EXPECT_GT(farPlaneShare(out("z/d16_perspective_distance466.png")), 0.5);
  EXPECT_LT(farPlaneShare(out("z/d16_perspective_distance29.png")), 0.01);
  EXPECT_NE(r.output.find("reversed"), std::string::npos) << "prints the table";
}

// The CPU studies open no device and write their CSV, chart and traces.
TEST_F(Cli, StudyAcneAndTirWriteCsvChartAndImages) {
  CommandResult acne = run("study acne -o " + out("acne") + " --size 80x45");
  ASSERT_EQ(acne.exitCode, 0) << acne.output;
  auto rows = csvRows(readText(out("acne/acne.csv")));
  ASSERT_EQ(rows.size(), 1u + 9) << "header + 9 epsilons";
  EXPECT_EQ(rows[0][0], "epsilon");
  EXPECT_EQ(rows[1][0], "0");
  expectDrawnChart(out("acne/acne.png"));
  EXPECT_EQ(pngSize(out("acne/trace_epsilon_0.png")), std::make_pair(80u, 45u));
  CommandResult tir = run("study tir -o " + out("tir") + " --size 32x32");
  ASSERT_EQ(tir.exitCode, 0) << tir.output;
  rows = csvRows(readText(out("tir/tir.csv")));
  ASSERT_EQ(rows.size(), 1u + 5 * 180) << "header + 5 iors x 180 angles";
  EXPECT_EQ(rows[0][5], "total_internal_reflection");
  expectDrawnChart(out("tir/tir.png"));
  EXPECT_EQ(pngSize(out("tir/snells_window_ior1.5.png")), std::make_pair(32u, 32u));
  EXPECT_NE(tir.output.find("asin(1/ior)"), std::string::npos) << tir.output;
}

TEST_F(Cli, StudyGouraudHighlightWritesCsvChartAndImages) {
  CommandResult r = run("study gouraud-highlight -o " + out("gh") + " --size 64x36");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("gh/gouraud-highlight.csv")));
  ASSERT_EQ(rows.size(), 1u + 8) << "header + 8 subdivisions";
  EXPECT_EQ(rows[1][1], "2");
  expectDrawnChart(out("gh/gouraud-highlight.png"));
  EXPECT_EQ(pngSize(out("gh/gouraud_8x8.png")), std::make_pair(64u, 36u));
}

TEST_F(Cli, StudyEnvVsTraceWritesCsvChartAndImages) {
  CommandResult r = run("study env-vs-trace -o " + out("evt") + " --size 96x54");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("evt/env-vs-trace.csv")));
  ASSERT_EQ(rows.size(), 1u + 4) << "header + 4 shading models";
  EXPECT_EQ(rows[0][4], "flip_hits_object");
  EXPECT_EQ(rows[3][0], "phong");
  expectDrawnChart(out("evt/env-vs-trace.png"));
  for (const char* image : {"evt/trace.png", "evt/regions.png", "evt/phong.png"})
    EXPECT_EQ(pngSize(out(image)), std::make_pair(96u, 54u)) << image;
}

TEST_F(Cli, StudyBumpSilhouetteWritesCsvChartAndImages) {
  CommandResult r = run("study bump-silhouette -o " + out("bs") + " --size 64x48");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("bs/bump-silhouette.csv")));
  ASSERT_EQ(rows.size(), 1u + 5) << "header + 5 tessellations";
  EXPECT_EQ(rows[0][7], "silhouette_difference");
  expectDrawnChart(out("bs/bump-silhouette.png"));
  EXPECT_EQ(pngSize(out("bs/displaced_1024.png")), std::make_pair(64u, 48u));
}

// Shadow-map studies against the tracer's exact shadows: the numbers must
// move the way the failure modes say, not only be written.
TEST_F(Cli, StudyShadowBiasMeasuresAcneFallingWithBias) {
  CommandResult r = run("study shadow-bias -o " + out("sb") + " --size 160x90");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("sb/shadow_bias.csv")));
  ASSERT_EQ(rows.size(), 1u + 2 * 4 * 8) << "header + 2 lights x 4 bias kinds x 8 values";
  EXPECT_EQ(rows[0][5], "acne_percent");
  std::map<std::string, double> acne;  // "light kind value" -> acne percent
  for (size_t i = 1; i < rows.size(); ++i)
    acne[rows[i][0] + " " + rows[i][1] + " " + rows[i][2]] = std::stod(rows[i][5]);
  for (const char* light : {"directional", "point"}) {
    std::string prefix = std::string(light) + " default-scaled ";
    EXPECT_GT(acne.at(prefix + "0"), 1.0) << light << ": no bias shows acne";
    EXPECT_LT(acne.at(prefix + "1"), 0.1) << light << ": the default bias keeps it under 0.1%";
  }
  expectDrawnChart(out("sb/shadow_bias.png"));
}

TEST_F(Cli, StudyShadowGrazingKeepsTheDefaultBiasFreeOfAcne) {
  CommandResult r = run("study shadow-grazing -o " + out("sg") + " --size 160x90");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("sg/shadow_grazing.csv")));
  ASSERT_EQ(rows.size(), 1u + 6 * 2 * 2) << "header + 6 elevations x 2 methods x 2 biases";
  EXPECT_EQ(rows[0][4], "acne_percent");
  for (size_t i = 1; i < rows.size(); ++i) {
    double acne = std::stod(rows[i][4]);
    if (rows[i][2] == "none")
      EXPECT_GT(acne, 1.0) << "no bias at " << rows[i][0] << " degrees";
    else
      EXPECT_LT(acne, 0.1) << "default bias at " << rows[i][0] << " degrees";
    EXPECT_LT(std::stod(rows[i][6]), 1.0) << "peter-panning at " << rows[i][0] << " degrees";
  }
  expectDrawnChart(out("sg/shadow_grazing.png"));
}

TEST_F(Cli, StudyShadowNearKeepsCastersBeforeTheNearPlane) {
  CommandResult r = run("study shadow-near -o " + out("sn") + " --size 160x90");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("sn/shadow_near.csv")));
  ASSERT_EQ(rows.size(), 1u + 2 * 8) << "header + 2 depth-clamp settings x 8 distances";
  EXPECT_EQ(rows[0][3], "depth_clamp");
  EXPECT_EQ(rows[0][6], "leak_percent");
  std::map<std::string, double> leak;  // "on|off distance" -> truly shadowed drawn lit, percent
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_GT(std::stoul(rows[i][4]), 10u) << "each distance has shadowed pixels to count";
    leak[rows[i][3] + " " + rows[i][0]] = std::stod(rows[i][6]);
  }
  for (const char* distance : {"0.3", "0.15", "0.1", "0.08", "0.065", "0.05", "0.04", "0.03"})
    EXPECT_LT(leak.at(std::string("on ") + distance), 1.0)
        << "with depth clamp the card casts at " << distance;
  // Without the clamp the failure the study is about shows where the card
  // crosses the near plane (0.05), and not before.
  EXPECT_LT(leak.at("off 0.1"), 1.0);
  EXPECT_GT(leak.at("off 0.04"), 50.0);
  EXPECT_GT(leak.at("off 0.03"), 90.0);
  expectDrawnChart(out("sn/shadow_near.png"));
  EXPECT_TRUE(std::filesystem::is_regular_file(out("sn/shadow_near_renders.png")));
}

TEST_F(Cli, StudyShadowEdgesMeasuresErrorAgainstMapSize) {
  CommandResult r = run("study shadow-edges -o " + out("se") + " --size 160x90");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("se/shadow_edges.csv")));
  ASSERT_EQ(rows.size(), 1u + 1 + 3 * 5) << "header + off + 3 methods x 5 sizes";
  EXPECT_EQ(rows[1][0], "off");
  double off = std::stod(rows[1][4]);
  double hard128 = std::stod(rows[2][4]), hard2048 = std::stod(rows[6][4]);
  EXPECT_EQ(rows[6][1], "2048");
  EXPECT_LT(hard2048, 0.5 * off) << "shadow maps remove most of the shadows' error";
  EXPECT_LT(hard2048, hard128) << "a finer map follows the traced edges better";
  expectDrawnChart(out("se/shadow_edges.png"));
}

TEST_F(Cli, StudyWithoutNameListsTheStudies) {
  CommandResult r = run("study");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* name : {"zfight", "acne", "tir", "gouraud-highlight", "env-vs-trace",
                           "bump-silhouette", "shadow-bias", "shadow-edges", "shadow-grazing",
                           "shadow-near", "lod-popping", "billboard-failures", "impostor-parallax"})
    EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
}

TEST_F(Cli, StudyRefusesAnUnknownNameAndWritesNothing) {
  CommandResult r = run("study nosuch -o " + out("s"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("study 'nosuch': expected one of zfight"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out("s")));
  r = run("study zfight -o " + out("s") + " --size 0x9");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("--size '0x9'"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out("s")));
}

const std::vector<std::string> kBenchColumns = {
    "scene",         "width",          "height",      "mode",
    "tessellation",  "msaa",           "filter",      "shadows",
    "shadow_size",   "triangles",      "frames",      "device_median_ms",
    "device_p95_ms", "wall_median_ms", "wall_p95_ms", "device_memory_mb",
    "peak_rss_mb",   "reference",      "rmse",        "psnr",
    "ssim",          "flip",           "lights",      "lod_error_px",
    "coarser_draws", "flip_vs_lod_off"};

TEST_F(Cli, BenchWritesCsvColumnsAndCharts) {
  CommandResult r = run("bench default -o " + out("b") +
                        " --size 64x36 --frames 3 --rounds 1 --modes flat,phong --tess 0.5,1 "
                        "--msaa 1,4 --reference raster --metric rmse");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("b/results.csv")));
  ASSERT_EQ(rows.size(), 1u + 2 * 2 * 2) << "header + models x tessellations x sample counts";
  EXPECT_EQ(rows[0], kBenchColumns);
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), kBenchColumns.size());
    EXPECT_EQ(rows[i][6], "material");
    EXPECT_EQ(rows[i][7], "hard") << "bench draws the shadows render draws";
    EXPECT_EQ(rows[i][8], "768");
    EXPECT_GT(std::stod(rows[i][15]), 0.0) << "device memory";
    EXPECT_GE(std::stod(rows[i][18]), 0.0) << "rmse";
    EXPECT_GT(std::stod(rows[i][19]), 10.0) << "psnr";
  }
  // The reference is Phong at 4x tessellation and 4x MSAA, so finer and
  // multisampled Phong errs less than coarse flat.
  EXPECT_EQ(rows[1][3], "flat");
  EXPECT_EQ(rows[8][3], "phong");
  EXPECT_LT(std::stod(rows[8][18]), std::stod(rows[1][18]));
  for (const char* chart : {"b/error_vs_time.png", "b/error_vs_triangles.png"}) {
    EXPECT_EQ(pngSize(out(chart)), std::make_pair(1100u, 640u)) << chart;
    expectDrawnChart(out(chart));
  }
  EXPECT_NE(r.output.find("Pareto front"), std::string::npos) << r.output;
}

// The texture filter is an axis too: on the receding checkerboard, nearest
// sampling (no mipmaps) errs more against the trilinear reference.
TEST_F(Cli, BenchSweepsTextureFilters) {
  CommandResult r = run("bench mip-plane -o " + out("f") +
                        " --size 96x54 --frames 3 --rounds 1 --modes phong --tess 1 --msaa 1 "
                        "--filters nearest,trilinear --reference raster --metric rmse");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("f/results.csv")));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][6], "nearest");
  EXPECT_EQ(rows[2][6], "trilinear");
  EXPECT_GT(std::stod(rows[1][18]), std::stod(rows[2][18])) << "rmse, nearest against trilinear";
  CommandResult bad = run("bench -o " + out("g") + " --filters blurry");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("--filters 'blurry'"), std::string::npos) << bad.output;
}

// Shadow method and map size are axes: off is one point, each method one
// per size; against the traced reference (shadow rays) shadows err less.
TEST_F(Cli, BenchSweepsShadowMethodsAndMapSizes) {
  CommandResult r = run("bench default -o " + out("s") +
                        " --size 96x54 --frames 3 --rounds 1 --modes phong --tess 1 --msaa 1 "
                        "--shadows off,hard,pcf3 --shadow-sizes 256,1024");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("s/results.csv")));
  ASSERT_EQ(rows.size(), 1u + 1 + 2 * 2) << "header + off + 2 methods x 2 sizes";
  EXPECT_EQ(rows[1][7], "off");
  EXPECT_EQ(rows[2][7], "hard");
  EXPECT_EQ(rows[2][8], "256");
  EXPECT_EQ(rows[5][7], "pcf3");
  EXPECT_EQ(rows[5][8], "1024");
  size_t flip = rows[0].size() - 5;
  ASSERT_EQ(rows[0][flip], "flip");
  ASSERT_EQ(rows[0][flip + 1], "lights");
  for (size_t i = 2; i < rows.size(); ++i)
    EXPECT_LT(std::stod(rows[i][flip]), std::stod(rows[1][flip])) << rows[i][7] << rows[i][8];
  CommandResult bad = run("bench -o " + out("t") + " --shadows soft");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("--shadows 'soft'"), std::string::npos) << bad.output;
  bad = run("bench -o " + out("t") + " --shadows hard --shadow-sizes 0");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("--shadow-sizes '0'"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(out("t")));
}

// Frame size and light count are axes too (issue 18's scaling charts): one
// row per size x count x model, the lights column counts the ring's lights,
// --reference none times without tracing, and scaling.png has a panel per
// axis that varies. (Which costs more is the benchmark's to say: tests do
// not assert on timing.)
TEST_F(Cli, BenchSweepsFrameSizesAndLightCounts) {
  CommandResult r = run("bench default -o " + out("sl") +
                        " --size 64x36,256x144 --lights 1,8 --frames 4 --rounds 1 "
                        "--modes unlit,phong --tess 1 --msaa 1 --reference none");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("sl/results.csv")));
  ASSERT_EQ(rows.size(), 1u + 2 * 2 * 2) << "header + sizes x light counts x models";
  const size_t lights = 22;
  ASSERT_EQ(rows[0][lights], "lights");
  std::set<std::string> settings;  // "mode width lights", each once
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i][17], "none");
    EXPECT_EQ(rows[i][18], "") << "no error measured";
    EXPECT_EQ(rows[i][9], rows[1][9]) << "the same triangles at every size and light count";
    EXPECT_GT(std::stod(rows[i][11]), 0.0) << "a device time measured";
    settings.insert(rows[i][3] + " " + rows[i][1] + "x" + rows[i][2] + " " + rows[i][lights]);
  }
  EXPECT_EQ(settings, (std::set<std::string>{"unlit 64x36 1", "phong 64x36 1", "unlit 64x36 8",
                                             "phong 64x36 8", "unlit 256x144 1", "phong 256x144 1",
                                             "unlit 256x144 8", "phong 256x144 8"}));
  EXPECT_EQ(rows[1][1], "64");
  EXPECT_EQ(rows[8][1], "256");
  EXPECT_EQ(rows[8][lights], "8");
  EXPECT_EQ(pngSize(out("sl/scaling.png")), std::make_pair(1040u, 420u)) << "two panels";
  EXPECT_FALSE(std::filesystem::exists(out("sl/error_vs_time.png"))) << "no error, no error chart";
  EXPECT_FALSE(std::filesystem::exists(out("sl/error_vs_triangles.png")));
  expectDrawnChart(out("sl/scaling.png"));
  for (const char* bad : {"--lights 9", "--lights 0", "--lights two", "--size 64x36,0x5"}) {
    CommandResult refused = run("bench default -o " + out("bad") + " " + bad);
    EXPECT_EQ(refused.exitCode, 2) << bad << "\n" << refused.output;
    EXPECT_NE(refused.output.find(std::string(bad).substr(0, 7)), std::string::npos)
        << refused.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out("bad")));
}

// Levels of detail are an axis (issue 17): off and each bound a row, each
// bound's image measured against off's with mean FLIP, charted in lod.png.
TEST_F(Cli, BenchSweepsLevelOfDetailBounds) {
  CommandResult r = run("bench lod -o " + out("lod") +
                        " --size 160x90 --lod off,2 --frames 3 --rounds 1 --modes phong "
                        "--tess 1 --msaa 1 --reference none");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto rows = csvRows(readText(out("lod/results.csv")));
  ASSERT_EQ(rows.size(), 3u) << "header, off, 2 px";
  size_t last = rows[0].size() - 1;
  ASSERT_EQ(rows[0][last], "flip_vs_lod_off");
  ASSERT_EQ(rows[0][last - 1], "coarser_draws");
  ASSERT_EQ(rows[0][last - 2], "lod_error_px");
  EXPECT_EQ(rows[1][last - 2], "0");
  EXPECT_EQ(rows[1][last - 1], "0");
  ASSERT_EQ(rows[1].size(), rows[0].size());
  EXPECT_EQ(rows[1][last], "") << "off has no FLIP against itself";
  ASSERT_EQ(rows[2].size(), rows[0].size());
  EXPECT_EQ(rows[2][last - 2], "2");
  EXPECT_GT(std::stoi(rows[2][last - 1]), 10);
  EXPECT_LT(std::stoull(rows[2][9]), std::stoull(rows[1][9]) / 4) << "triangles";
  double flip = std::stod(rows[2][last]);
  EXPECT_GT(flip, 0.0);
  EXPECT_LT(flip, 0.05);
  expectDrawnChart(out("lod/lod.png"));
  for (const char* bad : {"--lod 0", "--lod fine", "--lod 2,,4"}) {
    CommandResult refused = run("bench lod -o " + out("badlod") + " " + bad);
    EXPECT_EQ(refused.exitCode, 2) << bad << "\n" << refused.output;
    EXPECT_NE(refused.output.find("--lod"), std::string::npos) << refused.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out("badlod")));
}

// Progress with an ETA is drawn on a terminal only (issue 18): through a
// pipe (as every other test runs) trace and bench print their summary
// alone; under a pseudo-terminal (util-linux's `script`) the same commands
// redraw a progress line that ends at 100% with an ETA.
TEST_F(Cli, ProgressAndEtaShowOnATerminalOnly) {
  const std::string trace = "trace default -o " + out("p.png") + " --size 160x90 --spp 1";
  const std::string bench = "bench default -o " + out("pb") +
                            " --size 32x18 --frames 2 --rounds 2 --modes unlit,phong --tess 1 "
                            "--msaa 1 --reference none";
  for (const std::string& arguments : {trace, bench}) {
    CommandResult piped = run(arguments);
    ASSERT_EQ(piped.exitCode, 0) << piped.output;
    EXPECT_EQ(piped.output.find("ETA"), std::string::npos) << piped.output;
    EXPECT_EQ(piped.output.find('\r'), std::string::npos) << piped.output;
    EXPECT_EQ(piped.output.find("round 1/2"), std::string::npos) << piped.output;
  }
  auto onTerminal = [](const std::string& arguments) {
    return runShell("script -qec '" + std::string(SHADELAB_BINARY) + " " + arguments +
                    "' /dev/null 2>&1");
  };
  CommandResult traced = onTerminal(trace);
  ASSERT_EQ(traced.exitCode, 0) << traced.output;
  EXPECT_NE(traced.output.find("tracing: 100%"), std::string::npos) << traced.output;
  EXPECT_NE(traced.output.find("ETA"), std::string::npos) << traced.output;
  CommandResult benched = onTerminal(bench);
  ASSERT_EQ(benched.exitCode, 0) << benched.output;
  EXPECT_NE(benched.output.find("bench: 4/4, 100%"), std::string::npos) << benched.output;
  EXPECT_NE(benched.output.find("ETA"), std::string::npos) << benched.output;
}

// With bench results given, the loosest bound picks the row the CSV says is cheapest.
TEST_F(Cli, QualityWithLooseBoundPicksTheCheapestBenchedSetting) {
  auto rows = benchRows(
      "default --size 64x36 --frames 3 --rounds 1 --modes flat,gouraud,phong --tess 0.5,1 "
      "--msaa 1",
      out("b"));
  ASSERT_EQ(rows.size(), 7u);
  size_t cheapest = 1;
  for (size_t i = 2; i < rows.size(); ++i)
    if (std::stod(rows[i][11]) < std::stod(rows[cheapest][11])) cheapest = i;
  std::string expected = "chose " + rows[cheapest][3] + " t" + rows[cheapest][4] + " 1x";
  CommandResult r =
      run("render default -o " + out("q.png") + " --size 64x36 --quality 1000 --bench " + out("b"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  EXPECT_EQ(pngSize(out("q.png")), std::make_pair(64u, 36u));
}

// RMSE 0 is met only by the reference's own setting: Phong, 4x tessellation, 4x MSAA.
TEST_F(Cli, QualityWithTightestBoundPicksOnlyTheExactSetting) {
  CommandResult r = run("render default -o " + out("q.png") +
                        " --size 64x36 --msaa 4 --quality 0 --reference raster --metric rmse");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("chose phong t4 4x"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("quick sweep"), std::string::npos) << r.output;
}

// Without --reference and --metric, bench and render --quality measure mean
// FLIP against the traced reference: the CSV names it, the sweep says so,
// and a FLIP bound (which lies in 0..1) picks a setting that meets it.
TEST_F(Cli, BenchAndQualityDefaultToTheTracedReferenceAndFlip) {
  auto rows = benchRows(
      "spheres --size 64x36 --frames 3 --rounds 1 --modes phong --tess 1 --msaa 1", out("b"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][17], "trace");
  const double flip = std::stod(rows[1][21]);
  EXPECT_GT(flip, 0.0);
  EXPECT_LT(flip, 1.0);
  CommandResult r = run("render spheres -o " + out("q.png") + " --size 64x36 --quality 0.2");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("quality: flip <= 0.2, from a quick sweep against the trace reference"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("<- chosen"), std::string::npos) << r.output;
  // The sweep weighs shadows too, and says so of the candidates without them.
  EXPECT_NE(r.output.find(" no shadows "), std::string::npos) << r.output;
}

TEST_F(Cli, UnreachableQualityIsAnInputError) {
  CommandResult r =
      run("render default -o " + out("q.png") + " --size 64x36 --quality 99 --metric psnr");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("no setting reaches psnr >= 99"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, QualityWithModeIsAUsageError) {
  CommandResult r = run("render -o " + out("q.png") + " --quality 2 --mode flat");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("excludes"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, BenchFolderWithoutQualityIsAUsageError) {
  CommandResult r = run("render -o " + out("q.png") + " --bench " + out("b"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--quality"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

}  // namespace

TEST_F(Cli, ViewBadScriptLineNamesFileLineAndExpectation) {
  std::ofstream(out("script.txt")) << "frames 2\nkey 2\nfly 10\n";
  // The script is checked before any window opens: no X server needed.
  CommandResult r = run("view --script " + out("script.txt"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(out("script.txt") + ":3: 'fly 10': expected a step"), std::string::npos)
      << r.output;
}

TEST_F(Cli, ViewMissingScriptAndBadPresentModeAreInputErrors) {
  CommandResult missing = run("view --script " + out("none.txt"));
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  EXPECT_NE(missing.output.find("none.txt': No such file or directory"), std::string::npos)
      << missing.output;
  CommandResult mode = run("view --mode shiny");
  EXPECT_EQ(mode.exitCode, 2) << mode.output;
  EXPECT_NE(mode.output.find("--mode 'shiny': expected one of"), std::string::npos) << mode.output;
  CommandResult present = run("view --present vsync");
  EXPECT_EQ(present.exitCode, 2) << present.output;
  EXPECT_NE(present.output.find("--present 'vsync': expected fifo, mailbox or immediate"),
            std::string::npos)
      << present.output;
}

TEST_F(Cli, ViewWithoutDisplaySaysWhy) {
  CommandResult r = run("view", "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("cannot open a window"), std::string::npos) << r.output;
}
