// Honest file I/O (core/base/files.h): atomic writes that leave the whole
// file or nothing, and inputs refused unless they are regular files. Also
// the cost estimate of procedural shapes, checked against what is built.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/scene/shape.h"

namespace shadelab {
namespace {
namespace fs = std::filesystem;

class FileIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "files" /
          ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  size_t entries() const {
    return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
  fs::path dir;
};

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(FileIo, WriteLeavesOnlyTheCompleteTarget) {
  writeFileAtomically(dir / "a.txt", "first");
  writeFileAtomically(dir / "a.txt", "second, longer");
  EXPECT_EQ(readAll(dir / "a.txt"), "second, longer");
  EXPECT_EQ(entries(), 1u);  // no temporary beside it
}

// The target name is replaced, never written through: a link planted there
// keeps pointing at its file, which stays untouched.
TEST_F(FileIo, WriteReplacesALinkInsteadOfFollowingIt) {
  std::ofstream(dir / "victim.txt") << "keep";
  fs::create_symlink(dir / "victim.txt", dir / "out.txt");
  writeFileAtomically(dir / "out.txt", "new");
  EXPECT_EQ(readAll(dir / "victim.txt"), "keep");
  EXPECT_FALSE(fs::is_symlink(dir / "out.txt"));
  EXPECT_EQ(readAll(dir / "out.txt"), "new");
}

// A full disk, simulated by a file size limit in a child process (SIGXFSZ
// ignored, so write() fails with EFBIG): InputError with the reason, and
// neither the target nor a temporary is left.
TEST_F(FileIo, FailedWriteThrowsTheReasonAndLeavesNothing) {
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{4096, 4096};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      writeFileAtomically(dir / "big.bin", std::string(1 << 20, 'x'));
    } catch (const InputError& error) {
      std::string text = error.what();
      _exit(text == "cannot write '" + (dir / "big.bin").string() + "': File too large" ? 0 : 3);
    }
    _exit(4);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "3: other message, 4: no error";
  EXPECT_EQ(entries(), 0u);
}

// SIGTERM while a temporary is being written: the handler removes it before
// the process ends by the signal. The parent waits until the temporary of a
// 128 MiB write exists, then terminates the child.
TEST_F(FileIo, TerminatedWriteRemovesItsTemporary) {
  pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    writeFileAtomically(dir / "big.bin", std::string(size_t(128) << 20, 'y'));
    _exit(0);
  }
  auto temporaryExists = [&] {
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
      if (entry.path().filename().string().rfind(".big.bin.", 0) == 0) return true;
    return false;
  };
  bool seen = false;
  for (int i = 0; i < 20000 && !seen; ++i) {
    seen = temporaryExists();
    if (!seen) usleep(100);
  }
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(seen) << "the temporary never appeared";
  ASSERT_TRUE(WIFSIGNALED(status)) << "the write finished before the signal";
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(entries(), 0u) << "the temporary (or a partial target) was left";
}

TEST_F(FileIo, InputsMustBeRegularFilesWithinTheLimit) {
  ASSERT_EQ(mkfifo((dir / "pipe").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero");
  std::ofstream(dir / "ten") << "0123456789";
  auto message = [](const std::function<void()>& call) {
    try {
      call();
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  std::string pipe = (dir / "pipe").string(), zero = (dir / "zero").string();
  EXPECT_EQ(message([&] { readInputFile(pipe, "scene file", 100); }),
            "scene file '" + pipe + "' is a FIFO, expected a regular file");
  EXPECT_EQ(message([&] { readInputFile(zero, "texture", 100); }),
            "texture '" + zero + "' is a character device, expected a regular file");
  EXPECT_EQ(message([&] { checkInputFile(dir, "image", 100); }),
            "image '" + dir.string() + "' is a folder, expected a regular file");
  EXPECT_EQ(message([&] { readInputFile(dir / "ten", "buffer", 9); }),
            "buffer '" + (dir / "ten").string() + "' is 10 bytes, more than the 0 MiB allowed");
  EXPECT_EQ(readInputFile(dir / "ten", "buffer", 10), "0123456789");
}

// The estimate that refuses a request before building it is exact for every
// procedural shape that has no crease normals.
TEST(ShapeEstimate, MatchesTheBuiltMesh) {
  for (ShapeKind kind : {ShapeKind::Plane, ShapeKind::Box, ShapeKind::UvSphere,
                         ShapeKind::Icosphere, ShapeKind::Torus, ShapeKind::Teapot})
    for (float scale : {0.125f, 1.0f, 3.0f}) {
      ShapeDesc shape;
      shape.kind = kind;
      shape.tessellation = kind == ShapeKind::Icosphere ? 2 : 6;
      Mesh mesh = buildShape(shape, scale);
      MeshSize estimate = estimateShape(shape, scale);
      EXPECT_EQ(estimate.triangles, mesh.triangleCount()) << shapeKindName(kind) << " " << scale;
      EXPECT_GE(estimate.vertices, mesh.vertices.size()) << shapeKindName(kind) << " " << scale;
    }
}

}  // namespace
}  // namespace shadelab
