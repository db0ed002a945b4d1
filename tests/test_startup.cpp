// Start-up (issue 18): a command pays only for the libraries it uses.
// OpenImageIO (~260 shared libraries) sits behind libshadelab_oiio.so, loaded
// on first use; --help and a PNG render must never load it. The dynamic
// loader's own log (LD_DEBUG=files) names every object it opens, so each
// check has a twin that sees the module load (an EXR): the check can fail.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_command.h"

namespace {
namespace fs = std::filesystem;
using shadelab::test::CommandResult;
using shadelab::test::run;

class Startup : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "startup" /
          ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  std::string out(const std::string& name) const { return (dir / name).string(); }
  fs::path dir;
};

bool loadsOpenImageIo(const std::string& loaderLog) {
  return loaderLog.find("libOpenImageIO") != std::string::npos;
}
bool loadsModule(const std::string& loaderLog) {
  return loaderLog.find("libshadelab_oiio.so") != std::string::npos;
}

TEST_F(Startup, HelpLoadsNoOpenImageIo) {
  CommandResult r = run("--help", "LD_DEBUG=files");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_NE(r.output.find("file="), std::string::npos) << "no loader log: " << r.output;
  EXPECT_FALSE(loadsOpenImageIo(r.output));
  EXPECT_FALSE(loadsModule(r.output));
}

TEST_F(Startup, PngRenderLoadsNoOpenImageIo) {
  CommandResult r = run("render default --size 64x36 -o " + out("a.png"), "LD_DEBUG=files");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(out("a.png")));
  EXPECT_FALSE(loadsOpenImageIo(r.output));
  EXPECT_FALSE(loadsModule(r.output));
}

// The twin: an EXR needs the module, and the same log shows it.
TEST_F(Startup, ExrRenderLoadsTheModule) {
  CommandResult r = run("render default --size 64x36 -o " + out("a.exr"), "LD_DEBUG=files");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(out("a.exr")));
  EXPECT_TRUE(loadsOpenImageIo(r.output));
  EXPECT_TRUE(loadsModule(r.output));
}

// The binary itself does not link OpenImageIO (ldd lists every library
// bound at load); the module does, for the twin.
TEST_F(Startup, BinaryDoesNotLinkOpenImageIo) {
  CommandResult r = run("", "ldd");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(loadsOpenImageIo(r.output)) << r.output;
  fs::path module = fs::path(SHADELAB_BINARY).parent_path() / "libshadelab_oiio.so";
  CommandResult m = run("", "ldd " + module.string() + " #");
  ASSERT_EQ(m.exitCode, 0) << m.output;
  EXPECT_TRUE(loadsOpenImageIo(m.output)) << m.output;
}

// Without the module, a format that needs it is an input error naming the
// file and the reason, with nothing written; PNG still works.
TEST_F(Startup, MissingModuleIsAClearError) {
  std::string missing = "SHADELAB_OIIO_MODULE=" + out("no-such-module.so");
  CommandResult r = run("render default --size 64x36 -o " + out("a.exr"), missing);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("cannot write '" + out("a.exr") + "'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("OpenImageIO module"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no-such-module.so: no such file"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out("a.exr")));
  CommandResult png = run("render default --size 64x36 -o " + out("a.png"), missing);
  EXPECT_EQ(png.exitCode, 0) << png.output;
}

}  // namespace
