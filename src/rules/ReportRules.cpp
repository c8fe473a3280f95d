#include "rules/ReportRules.h"

#include <cmath>

#include "core/DirectionDef.h"

namespace tabletop::rules {
namespace {

// Closed intervals [lo1, hi1] and [lo2, hi2] share a point: either one's
// end lies within the other (report 3.6.1's "near or far face within").
bool overlapInclusive(double lo1, double hi1, double lo2, double hi2) {
  return (lo2 <= lo1 && lo1 <= hi2) || (lo2 <= hi1 && hi1 <= hi2) || (lo1 <= lo2 && lo2 <= hi1) ||
         (lo1 <= hi2 && hi2 <= hi1);
}

bool contains(double outerLo, double outerHi, double innerLo, double innerHi) {
  return outerLo <= innerLo && innerHi <= outerHi;
}

}  // namespace

Vec3 stepTarget(const Vec3& centre, double step, double angleDegrees) {
  return centre + pushDirection(angleDegrees) * step;
}

bool aligned(const Boundary& a, const Boundary& b) {
  return contains(a.left, a.right, b.left, b.right) || contains(b.left, b.right, a.left, a.right) ||
         contains(a.far, a.near, b.far, b.near) || contains(b.far, b.near, a.far, a.near);
}

bool cubesCollide(const Vec3& c1, double side1, const Vec3& c2, double side2, ForceAxis axis) {
  const Boundary b1 = cubeBoundary(c1, side1);
  const Boundary b2 = cubeBoundary(c2, side2);
  const double halfSum = 0.5 * (side1 + side2);
  if (axis == ForceAxis::X) {
    return std::abs(c1.x - c2.x) < halfSum && overlapInclusive(b1.far, b1.near, b2.far, b2.near);
  }
  return std::abs(c1.z - c2.z) < halfSum && overlapInclusive(b1.left, b1.right, b2.left, b2.right);
}

bool cubesCollideAsPrintedAlongZ(const Vec3& c1, double side1, const Vec3& c2, double side2) {
  const double lo2 = c2.x - 0.5 * side2, hi2 = c2.x + 0.5 * side2;
  const bool across = (lo2 <= c1.x - side1 && c1.x - side1 <= hi2) || (lo2 <= c1.x + side1 && c1.x + side1 <= hi2);
  return std::abs(c1.z - c2.z) < side1 + side2 && across;
}

bool spheresCollide(const Vec3& c1, double radius1, const Vec3& c2, double radius2) {
  return (c1 - c2).length() <= radius1 + radius2;
}

bool sphereStaysOnTable(const Vec3& centre, double step, double angleDegrees, const TableEdges& t) {
  const Vec3 target = stepTarget(centre, step, angleDegrees);
  return t.xLeft <= target.x && target.x <= t.xRight && t.zBack <= target.z && target.z <= t.zFront;
}

}  // namespace tabletop::rules
