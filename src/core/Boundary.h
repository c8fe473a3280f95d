#pragma once

#include "core/Vec3.h"

namespace tabletop {

/// The report's Boundary of a cube (report 3.2): the coordinates of its six
/// faces, for a cube at `centre` with side SL and no rotation.
struct Boundary {
  double left;    ///< X - SL/2
  double right;   ///< X + SL/2
  double top;     ///< Y + SL/2
  double bottom;  ///< Y - SL/2
  double far;     ///< Z - SL/2 (towards the back)
  double near;    ///< Z + SL/2 (towards the viewer)
};

/// Report 3.2: the Boundary of a cube of side `side` centred at `centre`.
constexpr Boundary cubeBoundary(const Vec3& centre, double side) {
  const double h = 0.5 * side;
  return {centre.x - h, centre.x + h, centre.y + h, centre.y - h, centre.z - h, centre.z + h};
}

}  // namespace tabletop
