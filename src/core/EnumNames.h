#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace tabletop {

/// One enum value and its name in files and on the command line. Each enum
/// keeps one table of these in its .cpp; the two lookups below are the only
/// code that reads them.
template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

/// The name `table` gives `value` ("" if it gives none).
template <class Enum, std::size_t N>
constexpr std::string_view nameOf(Enum value, const EnumName<Enum> (&table)[N]) {
  for (const EnumName<Enum>& e : table) {
    if (e.value == value) return e.name;
  }
  return {};
}

/// The value `table` names `name`, or nullopt.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> valueNamed(std::string_view name, const EnumName<Enum> (&table)[N]) {
  for (const EnumName<Enum>& e : table) {
    if (e.name == name) return e.value;
  }
  return std::nullopt;
}

/// The value among `values` whose toString() is `name`, or nullopt.
template <class Enum, std::size_t N>
std::optional<Enum> enumFromName(std::string_view name, const Enum (&values)[N]) {
  for (Enum v : values) {
    if (toString(v) == name) return v;
  }
  return std::nullopt;
}

}  // namespace tabletop
