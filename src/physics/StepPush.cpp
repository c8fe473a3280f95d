#include "physics/StepPush.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "physics/shapes/Sphere.h"

namespace tabletop {

double slidingDistance(double v0, double mu, double gravity) {
  return v0 * v0 / (2.0 * mu * gravity);
}

double rollingDistance(double v0, double mu, double rf, double radius, double gravity, double gyration) {
  const double rho = rf / radius, k = gyration;
  const double t1 = k * v0 / (gravity * ((1.0 + k) * mu - rho));
  const double v1 = v0 - mu * gravity * t1;
  const double rollDeceleration = gravity * rho / (1.0 + k);
  return 0.5 * (v0 + v1) * t1 + v1 * v1 / (2.0 * rollDeceleration);
}

double stepLaunchSpeed(const Shape& shape, double step, const Material& contact, double gravity,
                       double timestep, Integrator integrator) {
  const double mu = contact.friction;
  if (!(gravity > 0.0)) {
    throw std::invalid_argument("with no gravity nothing stops a push by step, which would give no impulse; "
                                "give this push an 'impulse' in N s");
  }
  if (!(mu > 0.0)) {
    throw std::invalid_argument("entity '" + shape.name() +
                                "' has no friction with the table, so a push by step never stops");
  }
  if (shape.kind() != ShapeKind::Sphere) {
    const double offset = integrator == Integrator::Euler ? 0.5 * mu * gravity * timestep : 0.0;
    return std::sqrt(step / slidingDistance(1.0, mu, gravity)) + offset;
  }
  const double r = static_cast<const Sphere&>(shape).radius();
  const double rf = contact.rollingFriction;
  if (!(rf > 0.0) || !(rf < mu * r)) {
    // A ball with no rolling friction rolls on for ever; one with more
    // than mu r never rolls and is not the ball of the closed form.
    std::ostringstream why;
    why << "sphere '" << shape.name() << "' needs a rolling friction above 0 and below friction * radius ("
        << mu * r << " m) for a push by step, got " << rf << " m; push it by 'impulse' instead";
    throw std::invalid_argument(why.str());
  }
  return std::sqrt(step / rollingDistance(1.0, mu, rf, r, gravity));
}

}  // namespace tabletop
