#include "core/scene/scene_json_fields.h"

#include <cctype>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>

#include "core/base/errors.h"

namespace shadelab::scene_json {
namespace {

const nlohmann::json kMissing;  // null: the value of `at` for an absent key

bool isIdentifier(std::string_view key) {
  if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  for (char c : key)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// camera.eye for plain keys, materials["dark wood"] for any other key.
std::string memberPath(const std::string& path, std::string_view key) {
  if (!isIdentifier(key)) return path + "[" + nlohmann::json(key).dump() + "]";
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

bool isArrayOf3Numbers(const nlohmann::json& value) {
  if (!value.is_array() || value.size() != 3) return false;
  for (const nlohmann::json& element : value)
    if (!element.is_number()) return false;
  return true;
}

}  // namespace

std::string describe(const nlohmann::json& value) {
  constexpr size_t kMaxLength = 60;
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > kMaxLength) text = text.substr(0, kMaxLength - 3) + "...";
  return text;
}

std::string formatNumber(float value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void Field::fail(const std::string& problem, const std::string& expected) const {
  throw InputError(*source_ + ": " + (path_.empty() ? "top level" : path_) + ": " + problem +
                   ", expected " + expected);
}

void Field::fail(const std::string& problemAndExpected) const {
  throw InputError(*source_ + ": " + (path_.empty() ? "top level" : path_) + ": " +
                   problemAndExpected);
}

void Field::wrongType(const std::string& expected) const {
  throw InputError(*source_ + ": " + (path_.empty() ? "top level" : path_) + ": expected " +
                   expected + ", got " + describe(json()));
}

void Field::expectObjectType() const {
  if (!json().is_object()) wrongType("an object");
}

bool Field::has(std::string_view key) const {
  expectObjectType();
  return json().contains(key);
}

std::optional<Field> Field::optional(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return at(key);
}

Field Field::required(std::string_view key, const std::string& expected) const {
  if (!has(key)) at(key).fail("missing", expected);
  return at(key);
}

Field Field::at(std::string_view key) const {
  expectObjectType();
  auto found = json().find(key);
  return Field(found == json().end() ? kMissing : *found, memberPath(path_, key), *source_);
}

void Field::expectObject(const Names& allowed) const {
  expectObjectType();
  for (const auto& [key, value] : json().items()) {
    bool known = false;
    for (std::string_view name : allowed) known = known || name == key;
    if (!known) at(key).fail("unknown field \"" + key + "\"", "one of " + joinNames(allowed));
  }
}

std::vector<std::pair<std::string, Field>> Field::members() const {
  expectObjectType();
  std::vector<std::pair<std::string, Field>> result;
  for (const auto& [key, value] : json().items()) result.emplace_back(key, at(key));
  return result;
}

std::vector<Field> Field::elements(const std::string& expected) const {
  if (!json().is_array()) wrongType(expected);
  std::vector<Field> result;
  for (size_t i = 0; i < json().size(); ++i)
    result.emplace_back(json()[i], path_ + "[" + std::to_string(i) + "]", *source_);
  return result;
}

float Field::number() const {
  if (!json().is_number()) wrongType("a number");
  float value = float(json().get<double>());
  if (!std::isfinite(value))
    fail(describe(json()) + " is too large for a float", "a finite number");
  return value;
}

float Field::positive() const {
  float value = number();
  if (!(value > 0.0f)) fail(describe(json()) + " is not positive", "a number > 0");
  return value;
}

float Field::nonNegative() const {
  float value = number();
  if (value < 0.0f) fail(describe(json()) + " is negative", "a number >= 0");
  return value;
}

uint32_t Field::integer(uint32_t min, uint32_t max, const std::string& meaning) const {
  std::string expected =
      "an integer in " + std::to_string(min) + ".." + std::to_string(max) + " (" + meaning + ")";
  if (!json().is_number()) wrongType(expected);
  double value = json().get<double>();
  if (value != std::floor(value)) fail(describe(json()) + " is not a whole number", expected);
  if (value < double(min) || value > double(max))
    fail(describe(json()) + " is out of range", expected);
  return uint32_t(value);
}

bool Field::boolean() const {
  if (!json().is_boolean()) wrongType("true or false");
  return json().get<bool>();
}

std::string Field::string() const {
  if (!json().is_string()) wrongType("a string");
  std::string text = json().get<std::string>();
  // A NUL ends the string wherever C reads it (file names, messages).
  if (text.find('\0') != std::string::npos)
    fail("a string with a NUL character (\\u0000)", "text without NUL characters");
  return text;
}

glm::vec3 Field::vec3() const {
  if (!isArrayOf3Numbers(json())) wrongType("an array of 3 numbers");
  std::vector<Field> parts = elements("an array of 3 numbers");
  return {parts[0].number(), parts[1].number(), parts[2].number()};
}

glm::vec3 Field::vec3OrNumber() const {
  if (json().is_number()) return glm::vec3(number());
  if (!isArrayOf3Numbers(json())) wrongType("a number or an array of 3 numbers");
  return vec3();
}

glm::vec3 Field::colour() const {
  if (json().is_number()) return glm::vec3(nonNegative());
  if (!isArrayOf3Numbers(json())) wrongType("a number or an array of 3 numbers");
  std::vector<Field> parts = elements("an array of 3 numbers");
  return {parts[0].nonNegative(), parts[1].nonNegative(), parts[2].nonNegative()};
}

size_t Field::choice(std::string_view what, const Names& names) const {
  std::string expected = "one of " + joinNames(names);
  if (!json().is_string()) wrongType("a string, " + expected);
  std::string value = json().get<std::string>();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == value) return i;
  fail("unknown " + std::string(what) + " " + describe(json()), expected);
}

nlohmann::json::parser_callback_t refuseDuplicateKeys(const std::string& source) {
  // The keys seen so far in each object being parsed, innermost last.
  auto open = std::make_shared<std::vector<std::set<std::string>>>();
  return [open, source](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) {
      open->emplace_back();
    } else if (event == Event::object_end) {
      if (!open->empty()) open->pop_back();
    } else if (event == Event::key && !open->empty()) {
      const std::string& key = parsed.get_ref<const std::string&>();
      if (!open->back().insert(key).second)
        throw InputError(source + ": JSON: the key \"" + key.substr(0, 64) +
                         "\" appears twice in one object; expected each key once (a parser "
                         "would keep the last silently)");
    }
    return true;
  };
}

}  // namespace shadelab::scene_json
