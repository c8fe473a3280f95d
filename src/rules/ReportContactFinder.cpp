#include "rules/ReportContactFinder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tabletop::rules {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A displacement component this small against the whole displacement is
// rounding (cos 90 degrees is 6e-17, not 0): the motion does not cross
// that axis, and the report's inclusive sideways test applies.
constexpr double kStill = 1e-12;

// 2D helpers in the table plane (x, z).
struct Flat {
  double x = 0.0;
  double z = 0.0;
};

double dot(Flat a, Flat b) { return a.x * b.x + a.z * b.z; }

Vec3 unitFlat(Flat v) {
  const double n = std::hypot(v.x, v.z);
  return n > 0.0 ? Vec3{v.x / n, 0.0, v.z / n} : Vec3{};
}

// The open interval of t in which |offset - t * d| < reach along one axis,
// or, when the axis is not crossed, everything or nothing by the inclusive
// test |offset| <= reach.
struct Interval {
  double enter;
  double exit;
};

Interval slab(double offset, double d, double reach, bool still) {
  if (still) return std::abs(offset) <= reach ? Interval{-kInf, kInf} : Interval{kInf, -kInf};
  const double a = (offset - reach) / d;
  const double b = (offset + reach) / d;
  return {std::min(a, b), std::max(a, b)};
}

// First t at which point p + t d enters the closed box |x| <= hx, |z| <= hz
// (negative when it starts inside), or +inf.
double rayBoxEntry(Flat p, Flat d, double hx, double hz) {
  double enter = -kInf, exit = kInf;
  const double ps[2] = {p.x, p.z}, ds[2] = {d.x, d.z}, hs[2] = {hx, hz};
  for (int k = 0; k < 2; ++k) {
    if (ds[k] == 0.0) {
      if (std::abs(ps[k]) > hs[k]) return kInf;
      continue;
    }
    const double a = (-hs[k] - ps[k]) / ds[k];
    const double b = (hs[k] - ps[k]) / ds[k];
    enter = std::max(enter, std::min(a, b));
    exit = std::min(exit, std::max(a, b));
  }
  return (enter <= exit && exit >= 0.0) ? enter : kInf;
}

// First t at which p + t d comes within r of c (negative when it starts
// within), or +inf.
double rayCircleEntry(Flat p, Flat d, Flat c, double r) {
  const Flat f{p.x - c.x, p.z - c.z};
  const double a = dot(d, d), b = dot(f, d), k = dot(f, f) - r * r;
  if (k <= 0.0) return -1.0;
  if (a == 0.0 || b >= 0.0) return kInf;
  const double disc = b * b - a * k;
  if (disc < 0.0) return kInf;
  return (-b - std::sqrt(disc)) / a;
}

std::optional<Hit> boxes(const RuleBody& a, const RuleBody& b, const Vec3& d) {
  const double scale = std::hypot(d.x, d.z);
  const Interval x = slab(b.position.x - a.position.x, d.x, a.footX() + b.footX(), std::abs(d.x) <= kStill * scale);
  const Interval z = slab(b.position.z - a.position.z, d.z, a.footZ() + b.footZ(), std::abs(d.z) <= kStill * scale);
  const double enter = std::max(x.enter, z.enter);
  const double exit = std::min(x.exit, z.exit);
  if (!(enter < exit) || exit <= 0.0 || enter > 1.0) return std::nullopt;
  const Flat offset{b.position.x - a.position.x, b.position.z - a.position.z};
  // Already overlapping: a contact only if the motion closes in.
  if (enter < 0.0 && dot(offset, {d.x, d.z}) <= 0.0) return std::nullopt;
  return Hit{std::max(enter, 0.0), unitFlat(offset)};
}

std::optional<Hit> spheres(const RuleBody& a, const RuleBody& b, const Vec3& d) {
  const double reach = a.halfExtents.x + b.halfExtents.x;
  // Cylinders stand upright: only two spheres meet off their equators.
  const bool bothSpheres = a.shape == ShapeKind::Sphere && b.shape == ShapeKind::Sphere;
  const double dy = bothSpheres ? b.position.y - a.position.y : 0.0;
  if (std::abs(dy) >= reach) return std::nullopt;
  const double flatReach = std::sqrt(reach * reach - dy * dy);
  // Centre of a relative to b moves from p along d; contact when |p| = flatReach.
  const Flat p{a.position.x - b.position.x, a.position.z - b.position.z};
  const double t = rayCircleEntry(p, {d.x, d.z}, {0.0, 0.0}, flatReach);
  if (!(t <= 1.0)) return std::nullopt;
  // Starting in contact: only a motion that closes in counts.
  if (t < 0.0 && dot(p, {d.x, d.z}) >= 0.0) return std::nullopt;
  const double at = std::max(t, 0.0);
  return Hit{at, unitFlat({-(p.x + at * d.x), -(p.z + at * d.z)})};
}

// A circle (sphere or cylinder) against a box's footprint: the circle's
// centre against the box grown by the radius with rounded corners.
std::optional<Hit> circleBox(const RuleBody& circle, const RuleBody& box, Flat relative, bool circleMoves) {
  double r = circle.halfExtents.x;
  if (circle.shape == ShapeKind::Sphere) {
    const double dy = std::max({0.0, box.bottom() - circle.position.y, circle.position.y - box.top()});
    if (dy >= r) return std::nullopt;
    r = std::sqrt(r * r - dy * dy);
  }
  const double hx = box.footX(), hz = box.footZ();
  const Flat p{circle.position.x - box.position.x, circle.position.z - box.position.z};
  const Flat d = circleMoves ? relative : Flat{-relative.x, -relative.z};
  double t = std::min(rayBoxEntry(p, d, hx + r, hz), rayBoxEntry(p, d, hx, hz + r));
  for (const Flat corner : {Flat{hx, hz}, Flat{-hx, hz}, Flat{hx, -hz}, Flat{-hx, -hz}}) {
    t = std::min(t, rayCircleEntry(p, d, corner, r));
  }
  if (!(t <= 1.0)) return std::nullopt;
  // Starting in contact: only a motion towards the box counts.
  if (t < 0.0 && dot(p, d) >= 0.0) return std::nullopt;
  const double at = std::max(t, 0.0);
  const Flat c{p.x + at * d.x, p.z + at * d.z};
  const Flat nearest{std::clamp(c.x, -hx, hx), std::clamp(c.z, -hz, hz)};
  Flat towardBox{nearest.x - c.x, nearest.z - c.z};
  if (dot(towardBox, towardBox) == 0.0) towardBox = {-c.x, -c.z};
  const Vec3 n = unitFlat(towardBox);
  return Hit{at, circleMoves ? n : n * -1.0};
}

}  // namespace

std::optional<Hit> ReportContactFinder::firstHit(std::size_t, const RuleBody& mover, std::size_t,
                                                 const RuleBody& other, const Vec3& d) const {
  if (mover.round() && other.round()) return spheres(mover, other, d);
  if (mover.round()) return circleBox(mover, other, {d.x, d.z}, true);
  if (other.round()) return circleBox(other, mover, {d.x, d.z}, false);
  return boxes(mover, other, d);
}

}  // namespace tabletop::rules
