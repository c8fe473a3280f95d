#pragma once

#include <cmath>

#include "core/Vec3.h"

namespace tabletop {

/// A plain unit quaternion (w, x, y, z) turning a body's axes into the
/// world's: v_world = q v_body q*. Bullet-free, for the core's closed forms.
struct Quat {
  double w = 1.0;
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  /// The turn by `angle` radians about the unit `axis`.
  static Quat about(const Vec3& axis, double angle) {
    const double s = std::sin(0.5 * angle);
    return {std::cos(0.5 * angle), axis.x * s, axis.y * s, axis.z * s};
  }
  /// This turn, then `o` in the axes this one leaves (the Hamilton product).
  Quat operator*(const Quat& o) const {
    return {w * o.w - x * o.x - y * o.y - z * o.z, w * o.x + x * o.w + y * o.z - z * o.y,
            w * o.y - x * o.z + y * o.w + z * o.x, w * o.z + x * o.y - y * o.x + z * o.w};
  }
  Quat conjugate() const { return {w, -x, -y, -z}; }
  Quat normalized() const {
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    return {w / n, x / n, y / n, z / n};
  }
  /// v turned by this quaternion.
  Vec3 rotate(const Vec3& v) const {
    const Quat r = *this * Quat{0.0, v.x, v.y, v.z} * conjugate();
    return {r.x, r.y, r.z};
  }
};

}  // namespace tabletop
