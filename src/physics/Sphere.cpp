#include "physics/Sphere.h"

#include "core/Angle.h"

namespace tabletop {

// A btSphereShape is a point with the radius as its margin: exact, so no
// margin choice is needed.
Sphere::Sphere(std::string name, double radius)
    : Shape(std::move(name), std::make_unique<btSphereShape>(radius)), radius_(radius) {}

double Sphere::volume() const { return 4.0 / 3.0 * kPi * radius_ * radius_ * radius_; }

btVector3 Sphere::localInertia(double mass) const {
  const double i = 0.4 * mass * radius_ * radius_;
  return btVector3(i, i, i);
}

}  // namespace tabletop
