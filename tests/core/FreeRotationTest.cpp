// The free rigid body's exact step (src/core/FreeRotation.cpp) against
// closed forms: Jacobi's functions against the elliptic integral they
// invert, the symmetric top's precession, a spin about a principal axis,
// the intermediate-axis flip at the time Euler's equations' solution gives,
// and the invariants at rates from 30 Hz to 1 kHz.

#include "core/FreeRotation.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "support/EulerFlip.h"

namespace tabletop {
namespace {

constexpr double kRates[] = {30, 60, 120, 240, 1000};

Vec3 boxMoments(double a, double b, double c) {
  return Vec3{b * b + c * c, a * a + c * c, a * a + b * b} * (1.0 / 12.0);
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Euler's equations in body axes, I w' = (I w) x w, by classical
// Runge-Kutta at `h` s, with the orientation's q' = q (0, w) / 2.
struct Tumbling {
  Quat q;
  Vec3 w;
};
Tumbling rungeKutta(const Vec3& I, Vec3 w, double seconds, double h) {
  const auto rate = [&](const Tumbling& s) {
    const Vec3 torque = cross(Vec3{I.x * s.w.x, I.y * s.w.y, I.z * s.w.z}, s.w);
    const Quat dq = s.q * Quat{0.0, 0.5 * s.w.x, 0.5 * s.w.y, 0.5 * s.w.z};
    return Tumbling{dq, {torque.x / I.x, torque.y / I.y, torque.z / I.z}};
  };
  const auto add = [](const Tumbling& s, const Tumbling& d, double f) {
    return Tumbling{{s.q.w + f * d.q.w, s.q.x + f * d.q.x, s.q.y + f * d.q.y, s.q.z + f * d.q.z}, s.w + d.w * f};
  };
  Tumbling s{Quat{}, w};
  for (long i = 0, n = std::lround(seconds / h); i < n; ++i) {
    const Tumbling k1 = rate(s), k2 = rate(add(s, k1, h / 2)), k3 = rate(add(s, k2, h / 2)), k4 = rate(add(s, k3, h));
    s = add(add(add(add(s, k1, h / 6), k2, h / 3), k3, h / 3), k4, h / 6);
    s.q = s.q.normalized();
  }
  return s;
}

// The angle between two orientations, rad.
double angleBetween(const Quat& a, const Quat& b) {
  const Quat d = a.conjugate() * b;
  return 2.0 * std::atan2(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), std::abs(d.w));
}

// am(F(phi)) = phi within a half turn, and a full period 4K later (K by
// the arithmetic-geometric mean, pi / (2 AGM(1, k'))) the amplitude has
// gone on by 2 pi. (libstdc++'s ellint_1 beyond a half turn adds its own
// K, which at m = 1 - 1e-6 is off by 7e-12 of itself, checked with mpmath.)
TEST(JacobiElliptic, InvertsTheEllipticIntegral) {
  for (double m : {0.0, 0.1, 0.5, 0.9, 0.999999, 1.0 - 1e-12}) {
    double a = 1.0, b = std::sqrt(1.0 - m);
    for (int i = 0; i < 40; ++i) std::tie(a, b) = std::make_pair(0.5 * (a + b), std::sqrt(a * b));
    const double K = std::acos(-1.0) / (2.0 * a);
    for (double phi : {-1.5, -0.3, 0.0, 0.7, 1.5}) {
      const double u = std::ellint_1(std::sqrt(m), phi);
      const JacobiElliptic j = jacobiElliptic(u, m);
      EXPECT_NEAR(j.am, phi, 1e-12) << m << " " << phi;
      EXPECT_NEAR(j.sn, std::sin(phi), 1e-13);
      EXPECT_NEAR(j.cn, std::cos(phi), 1e-13);
      EXPECT_NEAR(j.dn, std::sqrt(1.0 - m * std::sin(phi) * std::sin(phi)), 1e-13);
      EXPECT_NEAR(jacobiElliptic(u + 4.0 * K, m).am, phi + 2.0 * std::acos(-1.0), 1e-11 * K) << m << " " << phi;
    }
  }
}

// A spin about any principal axis (the middle one too, unstable) stays
// what it is, exactly, and the body turns about that axis at it.
TEST(FreeRotation, PrincipalSpinStaysExact) {
  const FreeRotation body{boxMoments(0.1, 0.2, 0.3)};
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 start{axis == 0 ? 5.0 : 0.0, axis == 1 ? 5.0 : 0.0, axis == 2 ? 5.0 : 0.0};
    Quat q;
    Vec3 w = start;
    for (int i = 0; i < 600; ++i) body.advance(q, w, 1.0 / 60.0);
    EXPECT_EQ(w, start);
    EXPECT_LT(angleBetween(q, Quat::about(start * 0.2, 50.0)), 1e-11);
  }
}

// Torque-free symmetric top, I_x = I_y: the spin about the symmetry axis
// stays, the spin across it turns about the axis in the body at
// (I_z - I_x) / I_x w_z, and the axis precesses about L at |L| / I_x.
TEST(FreeRotation, SymmetricTopPrecessesInClosedForm) {
  for (const Vec3 I : {Vec3{2, 2, 3}, Vec3{2, 2, 1}}) {
    const FreeRotation body{I};
    const Vec3 w0{0.8, -0.3, 4.0};
    const Vec3 L{I.x * w0.x, I.y * w0.y, I.z * w0.z};
    const double body_rate = (I.z - I.x) / I.x * w0.z, precession = L.length() / I.x;
    for (double hz : kRates) {
      Quat q;
      Vec3 w = w0;
      const int steps = static_cast<int>(std::lround(10.0 * hz));
      for (int i = 0; i < steps; ++i) body.advance(q, w, 1.0 / hz);
      const double t = steps / hz, c = std::cos(body_rate * t), s = std::sin(body_rate * t);
      const Vec3 expected{w0.x * c - w0.y * s, w0.x * s + w0.y * c, w0.z};
      EXPECT_LT((w - expected).length(), 1e-12 * w0.length()) << hz;
      const Vec3 axis = Quat::about(L * (1.0 / L.length()), precession * t).rotate({0, 0, 1});
      EXPECT_LT((q.rotate({0, 0, 1}) - axis).length(), 1e-11) << hz;
    }
  }
}

// The box spun at 5 rad/s about its middle axis, nudged by 1e-3 rad/s about
// the others, flips when the closed form says, within 0.1% at every rate
// (the sign change found between steps by linear interpolation); the
// closed form agrees with Runge-Kutta at 10 us to 1e-5 s.
TEST(FreeRotation, IntermediateAxisFlipsAtTheClosedFormTime) {
  const Vec3 I = boxMoments(0.3, 0.2, 0.1), w0{1e-3, 5.0, 1e-3};
  const double flip = test::closedFormFlip(I, w0);
  ASSERT_GT(flip, 0.0);
  const Tumbling before = rungeKutta(I, w0, flip - 1e-5, 1e-5), after = rungeKutta(I, w0, flip + 1e-5, 1e-5);
  EXPECT_GT(before.w.y, 0.0);
  EXPECT_LT(after.w.y, 0.0);
  const FreeRotation body{I};
  for (double hz : kRates) {
    Quat q;
    Vec3 w = w0;
    double found = -1.0;
    for (int i = 1; found < 0 && i <= 10 * hz; ++i) {
      const Vec3 last = w;
      body.advance(q, w, 1.0 / hz);
      if (w.y < 0) found = (i - w.y / (w.y - last.y)) / hz;
    }
    EXPECT_NEAR(found, flip, 1e-3 * flip) << hz;
  }
}

// Kinetic energy and the world's angular momentum over 10 s, for bodies
// circling their largest and their smallest axis, near the separatrix or
// not: within 1e-12 relative at every rate (rounding), and the orientation
// within 1e-7 rad of Runge-Kutta's.
TEST(FreeRotation, KeepsEnergyAndMomentumAndFollowsEulersEquations) {
  const struct {
    Vec3 I, w;
  } cases[] = {{boxMoments(0.1, 0.2, 0.3), {1e-3, 5.0, 1e-3}},
               {boxMoments(0.3, 0.2, 0.1), {0.01, 5.0, 0.01}},
               {{1, 2, 3}, {1, -2, 0.5}},
               {{3, 1, 2}, {0.3, 2, -4}},
               {{2, 3, 1}, {3, 1, -2}}};
  for (const auto& c : cases) {
    const FreeRotation body{c.I};
    const Vec3 L0 = body.momentum(c.w);
    const double E0 = body.energy(c.w);
    const Tumbling reference = rungeKutta(c.I, c.w, 10.0, 1e-4);
    for (double hz : kRates) {
      Quat q;
      Vec3 w = c.w;
      double energy = 0, momentum = 0;
      for (int i = 0; i < 10 * hz; ++i) {
        body.advance(q, w, 1.0 / hz);
        energy = std::max(energy, std::abs(body.energy(w) / E0 - 1.0));
        momentum = std::max(momentum, (q.rotate(body.momentum(w)) - L0).length() / L0.length());
      }
      EXPECT_LT(energy, 1e-12) << hz;
      EXPECT_LT(momentum, 1e-12) << hz;
      EXPECT_LT(angleBetween(q, reference.q), 1e-7) << hz;
    }
  }
}

}  // namespace
}  // namespace tabletop
