#pragma once

#include <optional>
#include <string>

#include "core/DirectionDef.h"
#include "core/Vec3.h"

namespace tabletop {

/// The report's Arrow (report 3.3.6): which entity the next force acts on and
/// in which direction. Not a body. For a cube or box the arrow sits on one of
/// the entity's faces (a DirectionDef, turning with its yaw); otherwise, or
/// when `face` is empty, it points along a world angle (report 3.8).
struct Arrow {
  std::string entity;
  std::optional<DirectionDef> face;  ///< the face pushed, if given by face
  double angleDegrees = 0.0;         ///< world angle when `face` is empty
  /// Where the push acts, m, in the body's frame from its centre (turning
  /// with it); none: the report's push, through the centre of mass.
  std::optional<Vec3> at = std::nullopt;

  /// The push's world angle (report 3.8) for an entity whose faces are
  /// turned by `entityYawDegrees` (0 for a sphere, whose faces do not exist).
  double worldAngleDegrees(double entityYawDegrees) const {
    return face ? directionAngleDegrees(*face) + entityYawDegrees : angleDegrees;
  }
};

/// How strong a push is: an impulse in N*s, or a step in metres (the impulse
/// that makes the entity, alone on the table, travel that far and stop).
struct PushMagnitude {
  enum class Kind { Impulse, Step };
  Kind kind = Kind::Step;
  double value = 0.0;
};

}  // namespace tabletop
