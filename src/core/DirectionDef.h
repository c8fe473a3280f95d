#pragma once

#include <optional>
#include <string_view>

#include "core/Vec3.h"

namespace tabletop {

/// The report's DirectionDef: named after the face the force acts on
/// (report 2). Left pushes towards +X, Right towards -X, Front towards -Z,
/// Back towards +Z.
enum class DirectionDef { Left, Right, Front, Back };

/// The report's name of a direction ("Left", ...).
std::string_view toString(DirectionDef d);

/// Parses a report direction name; nullopt if it is not one.
std::optional<DirectionDef> directionFromString(std::string_view name);

/// The push angle of a direction for an unrotated entity, in degrees, in the
/// convention of report 3.8 (angle from +X, positive towards -Z).
double directionAngleDegrees(DirectionDef d);

/// The horizontal unit vector of a push at `angleDegrees` (report 3.8):
/// X' = X + Step cos(Angle), Z' = Z - Step sin(Angle).
Vec3 pushDirection(double angleDegrees);

}  // namespace tabletop
