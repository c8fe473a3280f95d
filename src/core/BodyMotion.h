#pragma once

#include <array>

#include "core/Vec3.h"

namespace tabletop {

/// Where one entity is and how it moves: the part of an EntityState a
/// per-step check needs, without its name, status or support, so reading
/// it after every step costs no string or status work.
struct BodyMotion {
  Vec3 position;                                     ///< centre, metres
  std::array<double, 4> orientation{1.0, 0, 0, 0};  ///< unit quaternion w, x, y, z
  Vec3 linearVelocity;                               ///< m/s
  Vec3 angularVelocity;                              ///< rad/s
};

}  // namespace tabletop
