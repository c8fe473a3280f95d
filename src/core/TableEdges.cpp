#include "core/TableEdges.h"

namespace tabletop {

EntityPositionStatus dropStatus(const Vec3& c, const TableEdges& t) {
  if (c.x > t.xRight) return EntityPositionStatus::DropFromRightEdge;
  if (c.x < t.xLeft) return EntityPositionStatus::DropFromLeftEdge;
  if (c.z > t.zFront) return EntityPositionStatus::DropFromFrontEdge;
  if (c.z < t.zBack) return EntityPositionStatus::DropFromBackEdge;
  return EntityPositionStatus::OnTable;
}

bool overTableTop(const Vec3& c, double bottom, const TableEdges& t, double topHeight, double slack) {
  return dropStatus(c, t) == EntityPositionStatus::OnTable && bottom >= topHeight - slack;
}

double edgeCrossing(const Vec3& p0, const Vec3& v0, const Vec3& p1, double dt, EntityPositionStatus drop,
                    const TableEdges& t) {
  // The coordinate across the edge, and the edge's place on it.
  double a0 = p0.z, b0 = v0.z, a1 = p1.z, edge = 0.0;
  switch (drop) {
    case EntityPositionStatus::DropFromRightEdge: edge = t.xRight, a0 = p0.x, b0 = v0.x, a1 = p1.x; break;
    case EntityPositionStatus::DropFromLeftEdge: edge = t.xLeft, a0 = p0.x, b0 = v0.x, a1 = p1.x; break;
    case EntityPositionStatus::DropFromFrontEdge: edge = t.zFront; break;
    case EntityPositionStatus::DropFromBackEdge: edge = t.zBack; break;
    default: return 1.0;
  }
  // The quadratic from the start's place and velocity to the end's place,
  // on s in [0, 1]. The end's velocity is left out: once past the edge a
  // body begins to tip or fall, which bends its velocity, not yet its place.
  const auto at = [&](double s) { return a0 + b0 * dt * s + (a1 - a0 - b0 * dt) * s * s; };
  const double side0 = a0 - edge;
  if ((side0 > 0) == (a1 - edge > 0) || a1 == edge) return 1.0;
  // Bisection: the path starts on one side and ends on the other.
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    ((at(mid) - edge > 0) == (side0 > 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace tabletop
