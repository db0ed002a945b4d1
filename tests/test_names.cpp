// The name tables (core/base/names.h) that the command line, the scene format
// and messages share.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <set>

#include "core/base/errors.h"
#include "core/base/names.h"
#include "core/scene/procedural_textures.h"
#include "core/scene/scene.h"
#include "core/scene/shading.h"

namespace shadelab {
namespace {

enum class Colour { Red, Green, Blue };
constexpr NameTable<Colour, 3> kColours = {
    {{Colour::Red, "red"}, {Colour::Green, "green"}, {Colour::Blue, "blue"}}};

TEST(NameTable, LooksUpBothWays) {
  EXPECT_EQ(nameOf(kColours, Colour::Green), "green");
  EXPECT_EQ(valueOf(kColours, "blue"), Colour::Blue);
  EXPECT_FALSE(valueOf(kColours, "Blue").has_value()) << "names are case-sensitive";
  EXPECT_EQ(namesOf(kColours), (std::vector<std::string_view>{"red", "green", "blue"}));
  EXPECT_EQ(valuesOf(kColours), (std::array<Colour, 3>{Colour::Red, Colour::Green, Colour::Blue}));
  EXPECT_EQ(joinNames(namesOf(kColours), " | "), "red | green | blue");
}

TEST(NameTable, ABadNameNamesTheOptionTheValueAndTheChoices) {
  EXPECT_EQ(parseNamed(kColours, "red", "--colour"), Colour::Red);
  try {
    parseNamed(kColours, "mauve", "--colour");
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "--colour 'mauve': expected one of red, green, blue");
  }
}

// Each table names every enumerator once: a copy-paste slip (two entries with
// one name or one value) would make a value unreachable or ambiguous.
template <typename E, size_t N>
void expectOneToOne(const NameTable<E, N>& table, const char* what) {
  std::set<std::string_view> names;
  std::set<int> values;
  for (const NamedValue<E>& entry : table) {
    EXPECT_TRUE(names.insert(entry.name).second) << what << ": " << entry.name << " twice";
    EXPECT_TRUE(values.insert(int(entry.value)).second) << what << ": a value twice";
    EXPECT_FALSE(entry.name.empty()) << what;
  }
}

TEST(NameTable, EveryTableIsOneToOne) {
  expectOneToOne(kShadingModelNames, "shading models");
  expectOneToOne(kProjectionNames, "projections");
  expectOneToOne(kLightTypeNames, "light types");
  expectOneToOne(kTextureWrapNames, "wrap modes");
  expectOneToOne(kTextureFilterNames, "filters");
  expectOneToOne(kUvProjectionNames, "uv projections");
  expectOneToOne(kEnvironmentKindNames, "environment kinds");
  expectOneToOne(kHeightPatternNames, "height patterns");
  expectOneToOne(kOnOffNames, "switches");
  static constexpr NameTable<Colour, 2> kSlip = {{{Colour::Red, "red"}, {Colour::Green, "red"}}};
  EXPECT_NONFATAL_FAILURE(expectOneToOne(kSlip, "slip"), "red twice");
}

TEST(NameTable, ShadingModelsAreInTheShadersOrder) {
  // The enum's values are the shaders' specialization constants, 0..count-1.
  for (int i = 0; i < kShadingModelCount; ++i) EXPECT_EQ(int(kShadingModelNames[i].value), i);
}

TEST(SplitFields, KeepsEmptyFieldsAndInvertsJoin) {
  using Fields = std::vector<std::string>;
  EXPECT_EQ(splitFields(""), Fields{});
  EXPECT_EQ(splitFields("a"), Fields{"a"});
  EXPECT_EQ(splitFields("a,,b,"), (Fields{"a", "", "b", ""}));
  EXPECT_EQ(splitFields(",a"), (Fields{"", "a"}));
  EXPECT_EQ(splitFields(" a ; b", ';'), (Fields{" a ", " b"}));
  EXPECT_EQ(joinNames({"x", "y", "z"}, ","), "x,y,z");
  Fields fields = splitFields(joinNames({"x", "", "z"}, ","));
  EXPECT_EQ(fields, (Fields{"x", "", "z"}));
}

}  // namespace
}  // namespace shadelab
