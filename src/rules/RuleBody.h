#pragma once

#include <cmath>
#include <string>

#include "core/Angle.h"
#include "core/EntityPositionStatus.h"
#include "core/ShapeKind.h"
#include "core/Vec3.h"

namespace tabletop::rules {

/// What a RuleBody rests on when it is not another body (whose index it
/// then holds).
inline constexpr int kOnTable = -1;
inline constexpr int kOnGround = -2;
inline constexpr int kOnNothing = -3;

/// One entity as the report's rules see it: a footprint on the table (a
/// square or rectangle for cubes and boxes, a circle for spheres and
/// cylinders), a height, a centre and a status. No mass, no velocity: the
/// rules move entities by steps.
struct RuleBody {
  std::string name;
  ShapeKind shape = ShapeKind::Cube;
  Vec3 halfExtents;        ///< half sizes of the local bounding box, m
  double below = 0.0;      ///< centre to lowest point, m
  double above = 0.0;      ///< centre to highest point, m
  Vec3 position;           ///< centre, m
  double yawDegrees = 0.0; ///< turn about +Y (report 3.8 sense)
  EntityPositionStatus status = EntityPositionStatus::OnTable;
  int support = kOnTable;  ///< kOnTable, kOnGround, kOnNothing or a body index

  /// True when the footprint is a circle of radius halfExtents.x.
  bool round() const { return shape == ShapeKind::Sphere || shape == ShapeKind::Cylinder; }
  /// Half sizes of the footprint along world X and Z. A turned box uses
  /// the square that bounds it: report 3.6.1 is stated for rotation zero.
  double footX() const {
    if (round()) return halfExtents.x;
    const double a = convertAngle(yawDegrees);
    return std::abs(std::cos(a)) * halfExtents.x + std::abs(std::sin(a)) * halfExtents.z;
  }
  double footZ() const {
    if (round()) return halfExtents.x;
    const double a = convertAngle(yawDegrees);
    return std::abs(std::sin(a)) * halfExtents.x + std::abs(std::cos(a)) * halfExtents.z;
  }
  double bottom() const { return position.y - below; }
  double top() const { return position.y + above; }
};

}  // namespace tabletop::rules
