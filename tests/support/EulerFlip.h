#pragma once

#include <cmath>

#include "core/Vec3.h"

namespace tabletop::test {

/// When the middle axis' spin of a torque-free body first changes sign, s,
/// for principal moments I_x < I_y < I_z and a start spin w (body axes)
/// with L^2 > 2 T I_y (the spin circles z): Euler's equations' solution
/// (Landau and Lifshitz, Mechanics, 37) is w_y = A_y sn(u0 + lambda t), so
/// it crosses zero where u = 2K, K = K(k) the complete elliptic integral of
/// the first kind, k^2 = (I_y - I_x)(2 T I_z - L^2) / ((I_z - I_y)(L^2 - 2 T I_x)).
/// Returns -1 if the spin does not circle z, or starts on the separatrix
/// (k^2 within 1e-12 of 1: the flip takes forever, as a spin about the
/// middle axis alone).
inline double closedFormFlip(const Vec3& I, const Vec3& w) {
  const double twoT = I.x * w.x * w.x + I.y * w.y * w.y + I.z * w.z * w.z;
  const double L2 = I.x * I.x * w.x * w.x + I.y * I.y * w.y * w.y + I.z * I.z * w.z * w.z;
  const double m = (I.y - I.x) * (twoT * I.z - L2) / ((I.z - I.y) * (L2 - twoT * I.x));
  if (!(I.x < I.y && I.y < I.z && m > 0 && m < 1.0 - 1e-12)) return -1.0;
  const double rate = std::sqrt((I.z - I.y) * (L2 - twoT * I.x) / (I.x * I.y * I.z));
  const double Ax = std::sqrt((twoT * I.z - L2) / (I.x * (I.z - I.x)));
  const double Ay = std::sqrt((twoT * I.z - L2) / (I.y * (I.z - I.y)));
  const double u0 = std::ellint_1(std::sqrt(m), std::atan2(std::copysign(1.0, w.z) * w.y / Ay, w.x / Ax));
  const double K = std::comp_ellint_1(std::sqrt(m));
  return (2.0 * K * std::ceil(u0 / (2.0 * K)) - u0) / rate;
}

}  // namespace tabletop::test
