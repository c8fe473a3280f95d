#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <LinearMath/btScalar.h>

namespace tabletop {

/// The centre height at which a body whose resting centre height is `y`
/// is placed: seated a hair into its support, so the first collision pass
/// sees the contact. At exact touch rounding can leave a gap of an ulp,
/// which Bullet's box-box test reports as no contact; the body then falls
/// for one step before the solver catches it (docs/bullet-corrections.md). The seat
/// is 1 nm, or 8 ulps of the build's scalar at `y` if that is larger
/// (float: about 0.5 micrometre at 1 m).
inline double seated(double y) {
  const double ulps = 8.0 * std::numeric_limits<btScalar>::epsilon() * std::max(1.0, std::abs(y));
  return y - std::max(1e-9, ulps);
}

}  // namespace tabletop
