#pragma once

#include <optional>

#include <btBulletCollisionCommon.h>

namespace tabletop {

/// The two ends of a round solid about its own y axis, as the true solid
/// has them: a cylinder's rims, a truncated cone's two rings, a cone's ring
/// and its point (radius 0). Cylinder.cpp builds a cone as a hull whose
/// rings and point are drawn in by the margin; they are drawn out again
/// here. Index 0 is the -y end, 1 the +y end.
struct RoundEnds {
  btScalar y[2];       ///< m, in the solid's frame
  btScalar radius[2];  ///< m, 0 at a cone's point
};

/// Points of a hull level with each other, or at one distance from its
/// axis, within this, m.
inline constexpr btScalar kRingTolerance = 1e-9;

/// The points of `hull` at height `level` (within kRingTolerance): how
/// many, and their least and greatest distance from its y axis, m.
struct HullRing {
  int count = 0;
  btScalar low = BT_LARGE_FLOAT;
  btScalar high = 0;
};
HullRing hullRing(const btConvexHullShape& hull, btScalar level);

/// The ends of `shape` if it is a cylinder or a hull of two rings (or a
/// ring and a point) about its y axis; none for any other shape.
std::optional<RoundEnds> roundEnds(const btCollisionShape& shape);

}  // namespace tabletop
