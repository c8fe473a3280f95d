#include "core/ShapeGeometry.h"

#include <algorithm>
#include <cmath>

#include "core/Angle.h"

namespace tabletop {
namespace {

// Integrals over the height of r(y) = R + (r - R) y / h, the radius at
// height y above the base: A0 = int r^2, A1 = int y r^2, A2 = int y^2 r^2,
// B4 = int r^4. A frustum's mass properties follow from them.
struct FrustumIntegrals {
  double a0, a1, a2, b4;
};

FrustumIntegrals integrals(double R, double r, double h) {
  return {h * (R * R + R * r + r * r) / 3.0,
          h * h * (R * R + 2.0 * R * r + 3.0 * r * r) / 12.0,
          h * h * h * (R * R + 3.0 * R * r + 6.0 * r * r) / 30.0,
          h * (R * R * R * R + R * R * R * r + R * R * r * r + R * r * r * r + r * r * r * r) / 5.0};
}

}  // namespace

ShapeGeometry ShapeGeometry::cube(double side) { return {ShapeKind::Cube, side, side, side}; }
ShapeGeometry ShapeGeometry::sphere(double radius) { return {ShapeKind::Sphere, radius, radius, radius}; }
ShapeGeometry ShapeGeometry::box(double width, double height, double depth) {
  return {ShapeKind::SolidBox, width, height, depth};
}
ShapeGeometry ShapeGeometry::cylinder(double baseRadius, double topRadius, double height) {
  return {ShapeKind::Cylinder, baseRadius, topRadius, height};
}

std::optional<ShapeGeometry> ShapeGeometry::fromSizes(ShapeKind kind, const std::vector<double>& s) {
  switch (kind) {
    case ShapeKind::Cube: return s.size() == 1 ? std::optional(cube(s[0])) : std::nullopt;
    case ShapeKind::Sphere: return s.size() == 1 ? std::optional(sphere(s[0])) : std::nullopt;
    case ShapeKind::SolidBox: return s.size() == 3 ? std::optional(box(s[0], s[1], s[2])) : std::nullopt;
    case ShapeKind::Cylinder: return s.size() == 3 ? std::optional(cylinder(s[0], s[1], s[2])) : std::nullopt;
  }
  return std::nullopt;
}

std::vector<double> ShapeGeometry::sizes() const {
  if (kind_ == ShapeKind::Cube || kind_ == ShapeKind::Sphere) return {a_};
  return {a_, b_, c_};
}

double ShapeGeometry::centroidHeight() const {
  if (kind_ != ShapeKind::Cylinder) return halfExtents().y;
  const FrustumIntegrals k = integrals(a_, b_, c_);
  return k.a1 / k.a0;
}

Vec3 ShapeGeometry::halfExtents() const {
  switch (kind_) {
    case ShapeKind::Sphere: return {a_, a_, a_};
    case ShapeKind::Cylinder: {
      const double rmax = std::max(a_, b_);
      return {rmax, std::max(below(), above()), rmax};
    }
    case ShapeKind::Cube:
    case ShapeKind::SolidBox: break;
  }
  return {a_ * 0.5, b_ * 0.5, c_ * 0.5};
}

double ShapeGeometry::below() const { return kind_ == ShapeKind::Cylinder ? centroidHeight() : halfExtents().y; }

// The body's axes in the world: column i of the turn is q (e_i). Along -Y
// a box reaches sum_i h_i |(q e_i).y|; a rim of radius r about the axis a
// at height t on it reaches -t a.y + r sqrt(1 - a.y^2).
double ShapeGeometry::below(const Quat& q) const {
  switch (kind_) {
    case ShapeKind::Sphere: return a_;
    case ShapeKind::Cylinder: {
      const double ay = q.rotate({0, 1, 0}).y;
      const double across = std::sqrt(std::max(0.0, 1.0 - ay * ay));
      const double yc = centroidHeight();
      return std::max(yc * ay + a_ * across, -(c_ - yc) * ay + b_ * across);
    }
    case ShapeKind::Cube:
    case ShapeKind::SolidBox: break;
  }
  const Vec3 h = halfExtents();
  return h.x * std::abs(q.rotate({1, 0, 0}).y) + h.y * std::abs(q.rotate({0, 1, 0}).y) +
         h.z * std::abs(q.rotate({0, 0, 1}).y);
}

double ShapeGeometry::above() const {
  return kind_ == ShapeKind::Cylinder ? c_ - centroidHeight() : halfExtents().y;
}

double ShapeGeometry::volume() const {
  switch (kind_) {
    case ShapeKind::Sphere: return 4.0 / 3.0 * kPi * a_ * a_ * a_;
    case ShapeKind::Cylinder: return kPi * integrals(a_, b_, c_).a0;
    case ShapeKind::Cube:
    case ShapeKind::SolidBox: break;
  }
  const Vec3 h = halfExtents();
  return 8.0 * h.x * h.y * h.z;
}

Vec3 ShapeGeometry::inertia(double mass) const {
  switch (kind_) {
    case ShapeKind::Sphere: {
      const double i = 0.4 * mass * a_ * a_;
      return {i, i, i};
    }
    case ShapeKind::Cylinder: {
      // Per unit density: I_axis = pi B4 / 2; about a base diameter
      // pi (B4 / 4 + A2); the parallel-axis theorem moves that to the centroid.
      const FrustumIntegrals k = integrals(a_, b_, c_);
      const double yc = k.a1 / k.a0;
      const double axial = mass * k.b4 / (2.0 * k.a0);
      const double transverse = mass * (k.b4 / 4.0 + k.a2) / k.a0 - mass * yc * yc;
      return {transverse, axial, transverse};
    }
    case ShapeKind::Cube:
    case ShapeKind::SolidBox: break;
  }
  const Vec3 h = halfExtents();
  const double a2 = 4.0 * h.x * h.x, b2 = 4.0 * h.y * h.y, c2 = 4.0 * h.z * h.z;
  return {mass * (b2 + c2) / 12.0, mass * (a2 + c2) / 12.0, mass * (a2 + b2) / 12.0};
}

double ShapeGeometry::boundingRadius() const {
  if (kind_ == ShapeKind::Sphere) return a_;
  if (kind_ == ShapeKind::Cylinder) return std::hypot(std::max(a_, b_), std::max(below(), above()));
  return halfExtents().length();
}

double ShapeGeometry::smallestHalfDimension() const {
  switch (kind_) {
    case ShapeKind::Sphere: return a_;
    case ShapeKind::Cylinder: {
      // A cone's point is no size: its base is.
      const double radius = std::min(a_, b_) > 0 ? std::min(a_, b_) : std::max(a_, b_);
      return std::min(radius, 0.5 * c_);
    }
    case ShapeKind::Cube:
    case ShapeKind::SolidBox: break;
  }
  return 0.5 * std::min({a_, b_, c_});
}

std::pair<double, double> ShapeGeometry::topFootprint(double yawDegrees) const {
  if (kind_ == ShapeKind::Sphere) return {a_, a_};
  if (kind_ == ShapeKind::Cylinder) return {b_, b_};
  const Vec3 h = halfExtents();
  const double t = convertAngle(yawDegrees);
  const double c = std::abs(std::cos(t)), s = std::abs(std::sin(t));
  return {c * h.x + s * h.z, s * h.x + c * h.z};
}

}  // namespace tabletop
