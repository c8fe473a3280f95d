#pragma once

#include <optional>
#include <string_view>

namespace tabletop {

/// The value among `values` whose toString() is `name`, or nullopt.
template <class Enum, std::size_t N>
std::optional<Enum> enumFromName(std::string_view name, const Enum (&values)[N]) {
  for (Enum v : values) {
    if (toString(v) == name) return v;
  }
  return std::nullopt;
}

}  // namespace tabletop
