#pragma once

#include <algorithm>

namespace tabletop {

/// The collision margin of a body whose smallest half extent is
/// `halfExtent` metres: 5% of it, never above Bullet's 4 cm default.
///
/// Bullet's default margin (0.04 m) is larger than a few-centimetre cube's
/// half side; a btBoxShape takes its margin from inside its half extents,
/// so its inner core would be negative. Scaling the margin with the body
/// keeps every shape's outer surface exact (boxes and cylinders keep their
/// size, spheres use their radius as margin) and keeps GJK's rounded
/// corners to 5% of the smallest half extent.
inline double collisionMargin(double halfExtent) { return std::min(0.04, 0.05 * halfExtent); }

}  // namespace tabletop
