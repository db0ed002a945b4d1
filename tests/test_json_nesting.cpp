// Deeply nested JSON is refused before a recursive parser can overflow the
// stack: the check itself, scene files, .gltf and the GLB header.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/base/errors.h"
#include "core/base/json_nesting.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/scene_json.h"

namespace shadelab {
namespace {

using ::testing::HasSubstr;

std::string nested(size_t depth, std::string_view inner = "1") {
  return std::string(depth, '[') + std::string(inner) + std::string(depth, ']');
}

std::string errorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no InputError)";
}

TEST(JsonNesting, AllowsTheLimitAndRefusesOneMore) {
  EXPECT_NO_THROW(checkJsonNesting(nested(256), "a.json"));
  EXPECT_EQ(errorOf([] { checkJsonNesting("{\n\"a\": " + nested(257), "a.json"); }),
            "a.json: JSON nests deeper than 256 levels of arrays and objects (at line 2)");
  EXPECT_NO_THROW(checkJsonNesting(nested(3), "a.json", 3));
  EXPECT_THAT(errorOf([] { checkJsonNesting(nested(4), "a.json", 3); }), HasSubstr("than 3"));
}

TEST(JsonNesting, BracketsInStringsDoNotCount) {
  std::string brackets = "\"" + std::string(1000, '[') + "\\\"" + std::string(1000, '{') + "\"";
  EXPECT_NO_THROW(checkJsonNesting("[" + brackets + "]", "a.json"));
  // After the string ends, brackets count again.
  EXPECT_THAT(
      errorOf([&] { checkJsonNesting("[" + brackets + "," + nested(300) + "]", "a.json"); }),
      HasSubstr("deeper than 256"));
}

TEST(JsonNesting, ASceneFileNestedTwoHundredThousandDeepIsAnInputError) {
  std::string text = "{\"extras\": " + nested(200000) + "}";
  EXPECT_THAT(errorOf([&] { parseSceneJson(text, "deep.json"); }),
              HasSubstr("deep.json: JSON nests deeper than 256"));
}

TEST(JsonNesting, AGltfNestedTwoHundredThousandDeepIsAnInputError) {
  std::string text = "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + nested(200000) + "}";
  std::vector<uint8_t> bytes(text.begin(), text.end());
  EXPECT_THAT(errorOf([&] { parseGltfScene(bytes, "deep.gltf"); }),
              HasSubstr("deep.gltf: JSON nests deeper than 256"));
}

TEST(GlbHeader, AVersionOtherThanTwoIsRefused) {
  std::ifstream in(std::string(SHADELAB_TEST_DATA_DIR) + "/triangle.glb", std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_GT(bytes.size(), 20u);
  EXPECT_NO_THROW(parseGltfScene(bytes, "triangle.glb"));
  uint32_t version = 99;
  std::memcpy(bytes.data() + 4, &version, 4);
  EXPECT_EQ(errorOf([&] { parseGltfScene(bytes, "v99.glb"); }),
            "v99.glb: invalid GLB: version 99 in the header, expected 2 (glTF 2.0)");
}

}  // namespace
}  // namespace shadelab
