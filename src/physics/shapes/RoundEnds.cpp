#include "physics/shapes/RoundEnds.h"

#include <algorithm>
#include <cmath>

namespace tabletop {
namespace {

// Points whose heights or radii differ by less than this are level, m.
constexpr btScalar kRing = 1e-9;

// The radius of the hull's points at height `level` if they make a ring
// (or one point on the axis), else a negative number.
btScalar ringAt(const btConvexHullShape& hull, btScalar level) {
  const btVector3* points = hull.getUnscaledPoints();
  int count = 0;
  btScalar low = BT_LARGE_FLOAT, high = 0;
  for (int p = 0; p < hull.getNumPoints(); ++p) {
    if (std::abs(points[p].y() - level) > kRing) continue;
    const btScalar r = std::hypot(points[p].x(), points[p].z());
    low = std::min(low, r), high = std::max(high, r), ++count;
  }
  if (count == 1 && high <= kRing) return 0;
  return count >= 3 && high - low <= kRing ? high : -1;
}

}  // namespace

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
    if (std::abs(points[p].y() - bottom) <= kRing || std::abs(points[p].y() - top) <= kRing) ++onLevels;
  }
  if (r0 < 0 || r1 < 0 || r0 + r1 <= 0 || onLevels != hull.getNumPoints()) return std::nullopt;
  const btScalar m = hull.getMargin();
  return RoundEnds{{bottom - m, top + m}, {r0 > 0 ? r0 + m : 0, r1 > 0 ? r1 + m : 0}};
}

}  // namespace tabletop
