#pragma once

#include "core/Integrator.h"
#include "core/Material.h"

namespace tabletop {

class Shape;

/// Distance a body slides after being launched at `v0` m/s on a surface with
/// Coulomb friction `mu`: d = v0^2 / (2 mu g).
double slidingDistance(double v0, double mu, double gravity);

/// Distance a round body of `radius` travels after a push through its
/// centre launches it at `v0` without spin, on a contact with friction `mu`
/// and rolling friction `rf` (a lever arm in metres, as Bullet's), where
/// `gyration` is k^2 / r^2 about the axis it rolls on (2/5 for a solid
/// sphere, 1/2 for a solid cylinder lying on its side):
///  - it first slips: v falls at mu g while the friction and the rolling
///    resistance spin it up, d(w r)/dt = g (mu - rf / r) / k, until v = w r
///    at t1 = k v0 / (g ((1 + k) mu - rf / r)), v1 = v0 - mu g t1 (5/7 v0
///    for a sphere and 2/3 v0 for a cylinder when rf = 0);
///  - it then rolls, decelerating at a = g rf / (r (1 + k)) (energy: the
///    rolling kinetic energy (1 + k) m v^2 / 2 is lost at the rate
///    rf m g v / r).
/// d = (v0 + v1) t1 / 2 + v1^2 / (2 a).
double rollingDistance(double v0, double mu, double rf, double radius, double gravity, double gyration = 0.4);

/// The speed a push must give `shape` (a cube or box slides, a sphere slips
/// then rolls, a cylinder slides on its base), alone on a surface whose
/// contact coefficients with it are `contact`, to travel `step` metres and
/// stop. Both distances above grow as v0^2, so v0 = sqrt(step / d(1)).
///
/// With the trapezoid integrator the closed form is the launch speed: a
/// sliding body stops exactly where v0^2 / (2 mu g) puts it.
///
/// With Bullet's own semi-implicit Euler, positions move with the velocity
/// at the end of each step: that is the leapfrog scheme, exact for
/// constant accelerations once velocities are read as belonging to
/// mid-steps. A push at time t then sets the velocity of t + dt/2, and a
/// sliding body's launch speed is raised by mu g dt / 2; without it a step
/// falls short by v0 dt / 2. A sphere takes no offset there: the plain
/// closed form lands closer than either half-step offset, and what remains
/// is the slip phase's first-order error (figures in
/// docs/bullet-corrections.md).
///
/// Throws std::invalid_argument when no finite step can be reached
/// (no friction; a sphere without rolling friction, or with rf >= mu r).
double stepLaunchSpeed(const Shape& shape, double step, const Material& contact, double gravity,
                       double timestep, Integrator integrator);

}  // namespace tabletop
