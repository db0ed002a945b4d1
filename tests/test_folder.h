#pragma once
// A fresh folder for the running test's files, in the build tree's test
// output (SHADELAB_TEST_OUTPUT_DIR/scratch/SUITE/TEST): nothing is left in
// /tmp, and no two tests (nor two clones' test runs) share a name. Each call
// empties it, so a test takes it once.
#include <gtest/gtest.h>

#include <filesystem>

namespace shadelab::test {

inline std::filesystem::path testFolder() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "scratch" /
                              test->test_suite_name() / test->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace shadelab::test
