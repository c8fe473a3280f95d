#pragma once

#include <optional>
#include <string_view>

namespace tabletop {

/// The report's entity shapes (report 3). SolidBox and Cylinder also make
/// up the Table.
enum class ShapeKind { Cube, Sphere, SolidBox, Cylinder };

/// The scenario-file name of a shape ("cube", "sphere", "box", "cylinder").
std::string_view toString(ShapeKind k);

/// Parses a scenario-file shape name; nullopt if it is not one.
std::optional<ShapeKind> shapeKindFromString(std::string_view name);

}  // namespace tabletop
