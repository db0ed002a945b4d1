#pragma once
// One name table per enum: the single list that the command line, the scene
// format, help texts and error messages all read, so a value is spelled in
// one place and a bad one gets the same message wherever it is typed.
//   inline constexpr NameTable<DepthMode, 2> kDepthNames = {{{DepthMode::D16, "d16"}, ...}};
//   nameOf(kDepthNames, mode) -> "d16";  valueOf(kDepthNames, "d16") -> DepthMode::D16
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/errors.h"

namespace shadelab {

template <typename E>
struct NamedValue {
  E value;
  std::string_view name;
};

template <typename E, size_t N>
using NameTable = std::array<NamedValue<E>, N>;

template <typename E, size_t N>
constexpr std::string_view nameOf(const NameTable<E, N>& table, E value) {
  for (const NamedValue<E>& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

template <typename E, size_t N>
constexpr std::optional<E> valueOf(const NameTable<E, N>& table, std::string_view name) {
  for (const NamedValue<E>& entry : table)
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

template <typename E, size_t N>
constexpr std::array<E, N> valuesOf(const NameTable<E, N>& table) {
  std::array<E, N> values{};
  for (size_t i = 0; i < N; ++i) values[i] = table[i].value;
  return values;
}

template <typename E, size_t N>
std::vector<std::string_view> namesOf(const NameTable<E, N>& table) {
  std::vector<std::string_view> names;
  for (const NamedValue<E>& entry : table) names.push_back(entry.name);
  return names;
}

// "a, b, c" (or with another separator).
std::string joinNames(const std::vector<std::string_view>& names,
                      std::string_view separator = ", ");

// The fields of `text` between separators, as typed (no trimming, no
// quoting): "a,,b," -> {"a", "", "b", ""}; "" -> {}. For the command line's
// comma lists and the CSV files shadelab writes itself.
std::vector<std::string> splitFields(std::string_view text, char separator = ',');

// The value named `text`, or InputError "WHAT 'TEXT': expected one of a, b, c".
template <typename E, size_t N>
E parseNamed(const NameTable<E, N>& table, std::string_view text, std::string_view what) {
  if (std::optional<E> value = valueOf(table, text)) return *value;
  throw InputError(std::string(what) + " '" + std::string(text) + "': expected one of " +
                   joinNames(namesOf(table)));
}

// The switches of the command line and the viewer: "on" and "off".
inline constexpr NameTable<bool, 2> kOnOffNames = {{{true, "on"}, {false, "off"}}};

}  // namespace shadelab
