#include "physics/shapes/Sphere.h"

#include "core/ShapeGeometry.h"

namespace tabletop {

// A btSphereShape is a point with the radius as its margin: exact, so no
// margin choice is needed.
Sphere::Sphere(std::string name, double radius)
    : Shape(std::move(name), std::make_unique<btSphereShape>(radius)), radius_(radius) {}

double Sphere::volume() const { return ShapeGeometry::sphere(radius_).volume(); }

btVector3 Sphere::localInertia(double mass) const {
  const Vec3 i = ShapeGeometry::sphere(radius_).inertia(mass);
  return btVector3(i.x, i.y, i.z);
}

}  // namespace tabletop
