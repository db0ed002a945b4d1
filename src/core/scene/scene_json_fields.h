#pragma once
// Reading JSON values with their place in the file. Every read knows its JSON
// path ("objects[1].material.kd"), so a failure can say which file, where, what
// was wrong and what was expected. Private to scene_json*.cpp.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/base/names.h"

namespace shadelab::scene_json {

using Names = std::vector<std::string_view>;

class Field {
 public:
  Field(const nlohmann::json& value, std::string path, const std::string& source)
      : value_(&value), path_(std::move(path)), source_(&source) {}

  const nlohmann::json& json() const { return *value_; }
  const std::string& path() const { return path_; }

  // Throws InputError "<source>: <path>: <problem>, expected <expected>".
  [[noreturn]] void fail(const std::string& problem, const std::string& expected) const;
  // For a problem whose message already says what was expected.
  [[noreturn]] void fail(const std::string& problemAndExpected) const;
  // Throws InputError "<source>: <path>: expected <expected>, got <the value>".
  [[noreturn]] void wrongType(const std::string& expected) const;

  // Objects. The lookups fail unless this is an object. `at` also works for a
  // missing key (its value is then null), to report a problem at that path.
  bool has(std::string_view key) const;
  std::optional<Field> optional(std::string_view key) const;
  Field required(std::string_view key, const std::string& expected) const;
  Field at(std::string_view key) const;
  // Fails at the first key not in `allowed`, listing them (catches "colour").
  void expectObject(const Names& allowed) const;
  std::vector<std::pair<std::string, Field>> members() const;

  // Fails unless an array; `expected` describes the whole array.
  std::vector<Field> elements(const std::string& expected) const;

  // Numbers must be finite once converted to float.
  float number() const;
  float positive() const;
  float nonNegative() const;
  // An integral number in min..max; `meaning` says what it counts.
  uint32_t integer(uint32_t min, uint32_t max, const std::string& meaning) const;
  std::string string() const;
  bool boolean() const;            // true or false
  glm::vec3 vec3() const;          // [x, y, z]
  glm::vec3 vec3OrNumber() const;  // [x, y, z], or n meaning [n, n, n]
  glm::vec3 colour() const;        // a number (grey) or [r, g, b], all >= 0
  // A string that must be one of `names`; returns its index. `what` names
  // the kind of value ("shape") for the message.
  size_t choice(std::string_view what, const Names& names) const;
  // The value of a name table (names.h) this field names.
  template <typename E, size_t N>
  E choose(std::string_view what, const NameTable<E, N>& table) const {
    return table[choice(what, namesOf(table))].value;
  }

 private:
  void expectObjectType() const;

  const nlohmann::json* value_;
  std::string path_;
  const std::string* source_;
};

// "a, b, c"
// A JSON value as written, shortened for messages.
std::string describe(const nlohmann::json& value);
// Shortest readable form of a float: 0.1, 100, 1e-06.
std::string formatNumber(float value);

// A callback for nlohmann::json::parse that throws InputError naming
// `source` and the key when an object holds a key twice: the parser would
// keep the last one and drop the first without a word.
nlohmann::json::parser_callback_t refuseDuplicateKeys(const std::string& source);

}  // namespace shadelab::scene_json
