#include "physics/Cylinder.h"

#include <algorithm>

#include "core/Angle.h"
#include "physics/CollisionMargin.h"

namespace tabletop {
namespace {

// Integrals over the height of r(y) = R + (r - R) y / h, the radius at
// height y above the base: A0 = int r^2, A1 = int y r^2, A2 = int y^2 r^2,
// B4 = int r^4. Mass properties of the solid follow from them.
struct FrustumIntegrals {
  double a0, a1, a2, b4;
};

FrustumIntegrals integrals(double R, double r, double h) {
  return {h * (R * R + R * r + r * r) / 3.0,
          h * h * (R * R + 2.0 * R * r + 3.0 * r * r) / 12.0,
          h * h * h * (R * R + 3.0 * R * r + 6.0 * r * r) / 30.0,
          h * (R * R * R * R + R * R * R * r + R * R * r * r + R * r * r * r + r * r * r * r) / 5.0};
}

constexpr int kHullSegments = 32;

std::unique_ptr<btCollisionShape> makeCylinder(double R, double r, double h) {
  const double margin = collisionMargin(std::min(std::max(R, r), 0.5 * h));
  if (R == r) {
    // btCylinderShape keeps its outer size and takes the margin from inside.
    auto c = std::make_unique<btCylinderShape>(btVector3(R, 0.5 * h, R));
    c->setMargin(margin);
    return c;
  }
  // A truncated cone as a convex hull of two rings around the centroid. A
  // hull grows outwards by its margin, so the rings are drawn in by it.
  auto hull = std::make_unique<btConvexHullShape>();
  const FrustumIntegrals k = integrals(R, r, h);
  const double yc = k.a1 / k.a0;
  const double m = std::min(margin, 0.5 * std::min(R, r));
  for (int i = 0; i < kHullSegments; ++i) {
    const double a = 2.0 * kPi * i / kHullSegments;
    const double c = std::cos(a), s = std::sin(a);
    hull->addPoint(btVector3((R - m) * c, -yc + m, (R - m) * s), false);
    hull->addPoint(btVector3((r - m) * c, h - yc - m, (r - m) * s), false);
  }
  hull->setMargin(m);
  hull->recalcLocalAabb();
  return hull;
}

}  // namespace

Cylinder::Cylinder(std::string name, double baseRadius, double topRadius, double height)
    : Shape(std::move(name), makeCylinder(baseRadius, topRadius, height)),
      baseRadius_(baseRadius),
      topRadius_(topRadius),
      height_(height) {}

double Cylinder::centroidHeight() const {
  const FrustumIntegrals k = integrals(baseRadius_, topRadius_, height_);
  return k.a1 / k.a0;
}

double Cylinder::volume() const { return kPi * integrals(baseRadius_, topRadius_, height_).a0; }

// Per unit density: I_axis = pi B4 / 2; about a base diameter
// pi (B4 / 4 + A2); the parallel-axis theorem moves that to the centroid.
btVector3 Cylinder::localInertia(double mass) const {
  const FrustumIntegrals k = integrals(baseRadius_, topRadius_, height_);
  const double yc = k.a1 / k.a0;
  const double axial = mass * k.b4 / (2.0 * k.a0);
  const double transverse = mass * (k.b4 / 4.0 + k.a2) / k.a0 - mass * yc * yc;
  return btVector3(transverse, axial, transverse);
}

btVector3 Cylinder::halfExtents() const {
  const double rmax = std::max(baseRadius_, topRadius_);
  return btVector3(rmax, std::max(below(), above()), rmax);
}

// At the centroid's height the radius is interpolated between base and top.
double Cylinder::surfaceDistance(const btVector3&) const {
  const double f = centroidHeight() / height_;
  return baseRadius_ + (topRadius_ - baseRadius_) * f;
}

}  // namespace tabletop
