#pragma once

#include "core/Quat.h"
#include "core/Vec3.h"

namespace tabletop {

/// Jacobi's elliptic functions of u for the parameter m = k^2 (0 <= m < 1)
/// and the amplitude am(u), continuous in u (sn = sin am, cn = cos am).
struct JacobiElliptic {
  double sn = 0.0;
  double cn = 1.0;
  double dn = 1.0;
  double am = 0.0;
};

/// By the arithmetic-geometric mean and the descending Landen transformation
/// (Abramowitz and Stegun 16.4), to rounding.
JacobiElliptic jacobiElliptic(double u, double m);

/// The torque-free motion of a rigid body, exactly: Euler's equations'
/// solution (Landau and Lifshitz, Mechanics, section 37). In the body's
/// principal axes the spin follows Jacobi's sn, cn, dn of a time scaled by
/// a rate of the moments and invariants; the body turns so that its angular
/// momentum stays fixed in the world, about which it turns by an angle
/// given by an elliptic integral of the third kind. Kinetic energy and
/// angular momentum are kept to rounding at any step; a body with two equal
/// moments precesses by the closed form of the symmetric top.
/// docs/free-rotation.md says why this method and what it costs.
struct FreeRotation {
  /// The body's principal moments of inertia, kg m^2, about its own axes.
  Vec3 moments;

  /// Advances `dt` seconds: `orientation` turns the body's axes into the
  /// world's, `bodySpin` is the angular velocity in the body's axes, rad/s.
  void advance(Quat& orientation, Vec3& bodySpin, double dt) const;

  /// The kinetic energy w.I w / 2, J (per unit of the moments' mass).
  double energy(const Vec3& bodySpin) const;
  /// The angular momentum I w in the body's axes.
  Vec3 momentum(const Vec3& bodySpin) const;
};

}  // namespace tabletop
