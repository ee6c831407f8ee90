#pragma once
// Name tables for enums: one constexpr array of {value, name} per enum, and the lookups
// every parser, summary and writer uses on it, so that a new value is named in one place.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

// The value's name in `table` ("unknown" for a value the table lacks).
template <class Enum, std::size_t N>
constexpr std::string_view enum_name(const std::array<EnumName<Enum>, N>& table, Enum value) {
  for (const EnumName<Enum>& e : table)
    if (e.value == value) return e.name;
  return "unknown";
}

// The value named `name` in `table`; nothing where no entry has that name.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> enum_value(const std::array<EnumName<Enum>, N>& table, std::string_view name) {
  for (const EnumName<Enum>& e : table)
    if (e.name == name) return e.value;
  return std::nullopt;
}

// Every name in `table`, in table order (for --help and completion lists).
template <class Enum, std::size_t N>
std::vector<std::string> enum_names(const std::array<EnumName<Enum>, N>& table) {
  std::vector<std::string> names;
  for (const EnumName<Enum>& e : table) names.emplace_back(e.name);
  return names;
}

// "a, b, c": the names for an error message that lists the valid choices.
template <class Enum, std::size_t N>
std::string enum_name_list(const std::array<EnumName<Enum>, N>& table) {
  std::string list;
  for (const EnumName<Enum>& e : table) list += (list.empty() ? "" : ", ") + std::string(e.name);
  return list;
}

}  // namespace prism
