#include "physics/shapes/RoundEnds.h"

#include <algorithm>
#include <cmath>

namespace tabletop {
namespace {

// The radius of the hull's points at height `level` if they make a ring
// (or one point on the axis), else a negative number.
btScalar ringAt(const btConvexHullShape& hull, btScalar level) {
  const HullRing ring = hullRing(hull, level);
  if (ring.count == 1 && ring.high <= kRingTolerance) return 0;
  return ring.count >= 3 && ring.high - ring.low <= kRingTolerance ? ring.high : -1;
}

}  // namespace

HullRing hullRing(const btConvexHullShape& hull, btScalar level) {
  const btVector3* points = hull.getUnscaledPoints();
  HullRing ring;
  for (int p = 0; p < hull.getNumPoints(); ++p) {
    if (std::abs(points[p].y() - level) > kRingTolerance) continue;
    const btScalar r = std::hypot(points[p].x(), points[p].z());
    ring.low = std::min(ring.low, r), ring.high = std::max(ring.high, r), ++ring.count;
  }
  return ring;
}

std::optional<RoundEnds> roundEnds(const btCollisionShape& shape) {
  if (shape.getShapeType() == CYLINDER_SHAPE_PROXYTYPE) {
    const auto& cylinder = static_cast<const btCylinderShape&>(shape);
    if (cylinder.getUpAxis() != 1) return std::nullopt;
    const btVector3 half = cylinder.getHalfExtentsWithMargin();
    return RoundEnds{{-half.y(), half.y()}, {half.x(), half.x()}};
  }
  if (shape.getShapeType() != CONVEX_HULL_SHAPE_PROXYTYPE) return std::nullopt;
  const auto& hull = static_cast<const btConvexHullShape&>(shape);
  const btVector3* points = hull.getUnscaledPoints();
  if (hull.getNumPoints() < 4) return std::nullopt;
  btScalar bottom = points[0].y(), top = points[0].y();
  for (int p = 1; p < hull.getNumPoints(); ++p) bottom = std::min(bottom, points[p].y()), top = std::max(top, points[p].y());
  const btScalar r0 = ringAt(hull, bottom), r1 = ringAt(hull, top);
  int onLevels = 0;
  for (int p = 0; p < hull.getNumPoints(); ++p) {
    if (std::abs(points[p].y() - bottom) <= kRingTolerance || std::abs(points[p].y() - top) <= kRingTolerance) ++onLevels;
  }
  if (r0 < 0 || r1 < 0 || r0 + r1 <= 0 || onLevels != hull.getNumPoints()) return std::nullopt;
  const btScalar m = hull.getMargin();
  return RoundEnds{{bottom - m, top + m}, {r0 > 0 ? r0 + m : 0, r1 > 0 ? r1 + m : 0}};
}

}  // namespace tabletop
