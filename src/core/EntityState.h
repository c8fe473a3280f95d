#pragma once

#include <array>
#include <string>

#include "core/EntityPositionStatus.h"
#include "core/ShapeKind.h"
#include "core/Support.h"
#include "core/Vec3.h"

namespace tabletop {

/// A snapshot of one entity, the same in every mode.
struct EntityState {
  std::string name;
  ShapeKind shape = ShapeKind::Cube;
  Vec3 position;                                     ///< centre, metres
  std::array<double, 4> orientation{1.0, 0, 0, 0};  ///< unit quaternion w, x, y, z
  double yawDegrees = 0.0;                           ///< heading about +Y
  Vec3 linearVelocity;                               ///< m/s
  Vec3 angularVelocity;                              ///< rad/s
  EntityPositionStatus status = EntityPositionStatus::OnTable;
  Support support;  ///< what holds it up now
};

}  // namespace tabletop
