// The shadelab binary as a user runs it: exit codes (0 success, 2 usage and
// input errors), messages that name what was wrong, and no file left behind.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {
namespace fs = std::filesystem;

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

CommandResult run(const std::string& arguments) {
  std::string command = std::string(SHADELAB_BINARY) + " " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

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

TEST_F(Cli, RenderWritesExrWhenAsked) {
  CommandResult r = run("render default -o " + out("a.exr") + " --size 32x32 --mode gouraud");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream file(out("a.exr"), std::ios::binary);
  unsigned char magic[4] = {};
  file.read(reinterpret_cast<char*>(magic), 4);
  EXPECT_EQ(magic[0], 0x76);  // OpenEXR magic 76 2f 31 01
  EXPECT_EQ(magic[1], 0x2f);
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
}

TEST_F(Cli, HelpSucceedsForEachCommand) {
  for (const char* command :
       {"--help", "render --help", "compare --help", "bench --help", "info --help"}) {
    CommandResult r = run(command);
    EXPECT_EQ(r.exitCode, 0) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("Usage"), std::string::npos) << command;
  }
}

std::string readText(const std::string& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST_F(Cli, RenderLoadsJsonSceneFile) {
  CommandResult r = run(std::string("render ") + SHADELAB_ASSET_DIR + "/scenes/three-spheres.json -o " +
                        out("a.png") + " --size 64x36");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(out("a.png")), std::make_pair(64u, 36u));
}

TEST_F(Cli, MalformedJsonSceneNamesFileAndField) {
  std::ofstream(out("bad.json")) << R"({"camera": {"eye": [0, 1], "at": [0, 0, 0]}, "objects": []})";
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

TEST_F(Cli, BadEnvValueIsAUsageError) {
  CommandResult r = run("render env -o " + out("a.png") + " --env maybe");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--env"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, TessellationOutOfRangeIsAUsageError) {
  CommandResult r = run("render -o " + out("a.png") + " --tess 0");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--tess"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, CompareWritesSheetAndNumbers) {
  CommandResult r = run("compare teapot -o " + out("sheet.png") + " --size 64x36 --modes flat,phong");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // Reference, flat and phong across; images above heatmaps and labels.
  auto [width, height] = pngSize(out("sheet.png"));
  EXPECT_GE(width, 3u * 64u);
  EXPECT_GE(height, 2u * 36u);
  std::string json = readText(out("sheet.json"));
  for (const char* key : {"\"flat\"", "\"phong\"", "\"rmse\"", "\"psnr\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << " in " << json;
  EXPECT_EQ(filesLeft(), 2u);
}

TEST_F(Cli, CompareUnknownModeIsAnInputError) {
  CommandResult r = run("compare -o " + out("sheet.png") + " --modes flat,shiny");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("shiny"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 0u);
}

TEST_F(Cli, BenchWritesOneCsvRowPerSetting) {
  CommandResult r = run("bench spheres -o " + out("bench") +
                        " --size 64x36 --frames 4 --rounds 2 --modes unlit,phong --tess 0.5,1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string csv = readText(out("bench/results.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 2) << csv;
  EXPECT_EQ(csv.rfind("scene,width,height,mode,tessellation,msaa,triangles,frames,", 0), 0u) << csv;
  // 2 rounds x (4 frames - 1 warm-up) steady frames per setting.
  EXPECT_NE(csv.find("spheres,64,36,phong,0.5,1,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",6,"), std::string::npos) << csv;
  EXPECT_NE(r.output.find("x floor"), std::string::npos) << r.output;
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
  std::ofstream(out("textured.json"))
      << R"({"objects": [{"name": "ball", "shape": "sphere",
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

}  // namespace
