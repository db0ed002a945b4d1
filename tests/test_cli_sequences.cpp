// render --turntable N and --camera-path FILE (issue 19): numbered frames,
// the right count and names, the cameras they claim (a frame is the single
// render of its camera, to the bit), the animated GIF, and nothing left
// behind when a sequence fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/base/image.h"
#include "run_command.h"

namespace {
namespace fs = std::filesystem;
using shadelab::test::CommandResult;
using shadelab::test::run;

class Sequences : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "sequences" /
          ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  std::string out(const std::string& name) const { return (dir / name).string(); }
  size_t filesLeft() const {
    return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
  }
  bool same(const std::string& a, const std::string& b) const {
    shadelab::ImageU8 first = shadelab::readImageU8(out(a));
    shadelab::ImageU8 second = shadelab::readImageU8(out(b));
    return first.width == second.width && first.height == second.height &&
           first.pixels == second.pixels;
  }
  fs::path dir;
};

const std::string kSmall = " --size 48x27 --shadows off";

TEST_F(Sequences, TurntableWritesNumberedFramesStartingAtTheSceneCamera) {
  CommandResult r = run("render default --turntable 4 -o " + out("spin.png") + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* name : {"spin-0001.png", "spin-0002.png", "spin-0003.png", "spin-0004.png"})
    EXPECT_TRUE(fs::exists(dir / name)) << name;
  EXPECT_EQ(filesLeft(), 4u);  // no spin.png, no spin-0005.png, no temporaries
  EXPECT_NE(r.output.find("wrote 4 frames"), std::string::npos) << r.output;
  // Frame 1 is the scene's own camera; the others have turned.
  ASSERT_EQ(run("render default -o " + out("single.png") + kSmall).exitCode, 0);
  EXPECT_TRUE(same("spin-0001.png", "single.png"));
  EXPECT_FALSE(same("spin-0001.png", "spin-0002.png"));
  EXPECT_FALSE(same("spin-0002.png", "spin-0003.png"));
}

// A run that fails part-way leaves an earlier run's files as they were:
// every output is staged beside its target and renamed only once all are
// written. Here frame 4 cannot be written (a folder has its name), so frames
// 1-3 of the second run, which are of another size, must not replace the
// first run's, and nothing staged may stay behind.
TEST_F(Sequences, FailedRunKeepsTheEarlierRunsFiles) {
  ASSERT_EQ(run("render default --turntable 3 -o " + out("spin.png") + kSmall).exitCode, 0);
  auto bytes = [&](const std::string& name) {
    std::ifstream in(dir / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string first = bytes("spin-0001.png"), third = bytes("spin-0003.png");
  fs::create_directory(dir / "spin-0004.png");
  CommandResult r =
      run("render default --turntable 4 -o " + out("spin.png") + " --size 64x36 --shadows off");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("spin-0004.png' is a folder"), std::string::npos) << r.output;
  EXPECT_EQ(bytes("spin-0001.png"), first);
  EXPECT_EQ(bytes("spin-0003.png"), third);
  EXPECT_EQ(filesLeft(), 4u);  // three frames and the folder: no staged files
}

// The same when the last step fails: frame 2's name becomes a folder after
// its check passed, while the sequence is still drawing, so the final
// renames fail at frame 2 after frame 1 has replaced the earlier file. That
// file is put back and no new or staged file stays.
TEST_F(Sequences, RenameFailingAtTheEndPutsTheEarlierFilesBack) {
  ASSERT_EQ(run("render default -o " + out("spin-0001.png") + kSmall).exitCode, 0);
  auto bytes = [&](const std::string& name) {
    std::ifstream in(dir / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string earlier = bytes("spin-0001.png");
  const std::string folder = (dir / "spin-0002.png").string();
  CommandResult r = run("render default --turntable 400 --size 320x180 -o " + out("spin.png") +
                        " 2>&1 & pid=$!; for i in $(seq 3000); do ls -A " + dir.string() +
                        " | grep -q 'spin-0002-staged' && break; sleep 0.01; done; mkdir " +
                        folder + "; wait $pid");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("cannot write '" + folder + "'"), std::string::npos) << r.output;
  EXPECT_TRUE(bytes("spin-0001.png") == earlier) << "frame 1 is not the earlier file";
  EXPECT_EQ(filesLeft(), 2u);  // the earlier frame and the folder
}

// A half turn of the default camera about the up axis through the look-at
// point puts the eye at (2 at.x - eye.x, eye.y, 2 at.z - eye.z): frame 3 of 4
// is the single render of that camera.
TEST_F(Sequences, TurntableHalfTurnIsTheMirroredEye) {
  std::string camera = " --eye 0,2,6 --at 0,0.5,0 --up 0,1,0 --fovy 45";
  ASSERT_EQ(run("render default --turntable 4 -o " + out("t.png") + kSmall + camera).exitCode, 0);
  std::string behind = " --eye 0,2,-6 --at 0,0.5,0 --up 0,1,0 --fovy 45";
  ASSERT_EQ(run("render default -o " + out("behind.png") + kSmall + behind).exitCode, 0);
  shadelab::ImageU8 turned = shadelab::readImageU8(out("t-0003.png"));
  shadelab::ImageU8 expected = shadelab::readImageU8(out("behind.png"));
  // The rotation is a float sin/cos of pi: allow a few pixels of rounding.
  size_t differing = 0;
  for (size_t i = 0; i < turned.pixels.size(); i += 4)
    differing += std::abs(int(turned.pixels[i]) - int(expected.pixels[i])) > 8;
  EXPECT_LT(differing, turned.pixels.size() / 4 / 100);
}

// With the validation layer on (a sequence once shut the device down while
// its renderer still held objects: 112 messages and an abort).
TEST_F(Sequences, TurntableGifHoldsEveryFrameAndLoops) {
  CommandResult r =
      run("--validate render default --turntable 3 --gif -o " + out("spin.png") + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("alidation"), std::string::npos) << r.output;
  EXPECT_EQ(filesLeft(), 4u);  // three frames and spin.gif
  std::ifstream file(dir / "spin.gif", std::ios::binary);
  std::stringstream bytes;
  bytes << file.rdbuf();
  std::string gif = bytes.str();
  EXPECT_EQ(gif.substr(0, 6), "GIF89a");
  EXPECT_NE(gif.find("NETSCAPE2.0"), std::string::npos);  // the loop extension: animated
  // One graphic control extension (the frame's delay) per frame.
  size_t frames = 0;
  for (size_t at = gif.find("\x21\xF9\x04"); at != std::string::npos;
       at = gif.find("\x21\xF9\x04", at + 3))
    ++frames;
  EXPECT_EQ(frames, 3u);
  shadelab::ImageU8 first = shadelab::readImageU8(out("spin.gif"));
  EXPECT_EQ(first.width, 48u);
  EXPECT_EQ(first.height, 27u);
}

const std::string kFront = R"({"eye": [0, 2, 6], "at": [0, 0.5, 0], "up": [0, 1, 0], "fovy": 45})";
const std::string kSide = R"({"eye": [6, 2, 0], "at": [0, 0.5, 0], "up": [0, 1, 0], "fovy": 30})";

TEST_F(Sequences, CameraPathListedFramesAreTheirCamerasRenders) {
  write("path.json", "[" + kFront + ", " + kSide + "]");
  CommandResult r =
      run("render default --camera-path " + out("path.json") + " -o " + out("p.png") + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "p-0001.png"));
  EXPECT_TRUE(fs::exists(dir / "p-0002.png"));
  EXPECT_FALSE(fs::exists(dir / "p-0003.png"));
  ASSERT_EQ(run("render default -o " + out("side.png") + kSmall +
                " --eye 6,2,0 --at 0,0.5,0 --up 0,1,0 --fovy 30")
                .exitCode,
            0);
  EXPECT_TRUE(same("p-0002.png", "side.png"));
}

TEST_F(Sequences, CameraPathInterpolatesBetweenKeys) {
  write("path.json", R"({"frames": 5, "cameras": [)" + kFront + ", " + kSide + "]}");
  write("keys.json", "[" + kFront + ", " + kSide + "]");
  ASSERT_EQ(run("render default --camera-path " + out("path.json") + " -o " + out("i.png") + kSmall)
                .exitCode,
            0);
  ASSERT_EQ(run("render default --camera-path " + out("keys.json") + " -o " + out("k.png") + kSmall)
                .exitCode,
            0);
  for (int frame = 1; frame <= 5; ++frame)
    EXPECT_TRUE(fs::exists(dir / ("i-000" + std::to_string(frame) + ".png"))) << frame;
  EXPECT_FALSE(fs::exists(dir / "i-0006.png"));
  // The ends are the keys; the middle is neither.
  EXPECT_TRUE(same("i-0001.png", "k-0001.png"));
  EXPECT_TRUE(same("i-0005.png", "k-0002.png"));
  EXPECT_FALSE(same("i-0003.png", "k-0001.png"));
  EXPECT_FALSE(same("i-0003.png", "k-0002.png"));
}

TEST_F(Sequences, JsonListsEveryFrame) {
  CommandResult r = run("render default --turntable 2 --gif --json -o " + out("j.png") + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("\"sequence\":\"turntable\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("j-0002.png\"]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"animation\":\"" + out("j.gif") + "\""), std::string::npos) << r.output;
}

}  // namespace
