#include "core/FreeRotation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace tabletop {
namespace {

using Axes = std::array<double, 3>;

Axes axes(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 vec(const Axes& a) { return {a[0], a[1], a[2]}; }
Vec3 unit(int axis) { return vec({axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0}); }

// Two moments closer than this share of the largest are taken as equal:
// the body is then a symmetric top (or a sphere), whose closed form needs
// no elliptic functions (their parameter tends to 0 or the rate to 0 there).
constexpr double kEqualMoments = 1e-9;

// The largest parameter m below 1 (on the separatrix, m = 1, the period is
// infinite; a body there but not at rest on it is taken a rounding inside).
constexpr double kLargestParameter = 1.0 - std::numeric_limits<double>::epsilon();

// The spacing of Boole's rule's nodes in the elliptic functions' argument
// (about radians of the spin's circling): its error, ~ h^6 of the step,
// stays below 1e-12 of a turn.
constexpr double kNodeSpacing = 0.025;

// Below this argument sn, cn and dn are summed from their series to u^9
// (the first term left out is below 1e-19).
constexpr double kSeriesArgument = 0.01;

// Jacobi's functions (no amplitude) of a small argument: the series
// (Abramowitz and Stegun 16.22) at u / 2^j below kSeriesArgument, doubled
// back j times (16.18). Cheaper than the means for the steps advance takes.
JacobiElliptic jacobiStep(double u, double m) {
  int doublings = 0;
  while (std::abs(u) > kSeriesArgument) {
    u *= 0.5;
    ++doublings;
  }
  const double u2 = u * u, m2 = m * m, m3 = m2 * m;
  double sn = u * (1 - u2 / 6 * ((1 + m) - u2 / 20 * ((1 + 14 * m + m2) - u2 / 42 * ((1 + 135 * m + 135 * m2 + m3) -
                                                                                       u2 / 72 * (1 + 1228 * m + 5478 * m2 + 1228 * m3 + m2 * m2)))));
  double cn = 1 - u2 / 2 * (1 - u2 / 12 * ((1 + 4 * m) - u2 / 30 * ((1 + 44 * m + 16 * m2) - u2 / 56 * (1 + 408 * m + 912 * m2 + 64 * m3))));
  double dn = 1 - u2 / 2 * m * (1 - u2 / 12 * ((4 + m) - u2 / 30 * ((16 + 44 * m + m2) - u2 / 56 * (64 + 912 * m + 408 * m2 + m3))));
  for (int i = 0; i < doublings; ++i) {
    const double s2 = sn * sn, den = 1 - m * s2 * s2;
    const double sn2 = 2 * sn * cn * dn / den;
    const double cn2 = (cn * cn - s2 * dn * dn) / den;
    dn = (dn * dn - m * s2 * cn * cn) / den;
    sn = sn2, cn = cn2;
  }
  return {sn, cn, dn, 0.0};
}

// A body with two equal moments `it` about the axes across its symmetry
// axis `s` (moment is): its angular momentum turns in the body about the
// axis at (1/is - 1/it) L_s while the body turns about the fixed angular
// momentum at |L| / it; the two turns commute, so this is exact at any dt.
void symmetricTop(int s, double is, double it, Quat& q, Axes& w, const Axes& L, double dt) {
  const double size = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
  const double body = (1.0 / is - 1.0 / it) * L[static_cast<std::size_t>(s)];
  const Vec3 along = vec(L) * (1.0 / size);
  q = (q * Quat::about(along, size * dt / it) * Quat::about(unit(s), body * dt)).normalized();
  w = axes(Quat::about(unit(s), -body * dt).rotate(vec(w)));
}

// The cosine and sine of half the angle whose cosine and sine are c and s
// (s >= 0 or not), without losing digits near either end.
std::pair<double, double> half(double c, double s) {
  if (c >= 0) {
    const double ch = std::sqrt(0.5 * (1.0 + c));
    return {ch, s / (2.0 * ch)};
  }
  const double sh = std::copysign(std::sqrt(0.5 * (1.0 - c)), s);
  return {s / (2.0 * sh), sh};
}

// Rx(theta) Rz(phi) of the Euler angles (psi, theta, phi) that turn the
// body's axes (a, b, p), cyclic, to axes whose third is along the angular
// momentum L (Landau and Lifshitz 35): L_body = |L| (sin theta sin phi,
// sin theta cos phi, cos theta). L must not lie along p. The product of the
// two half-angle quaternions is written out (a x p = -b).
Quat towardsMomentum(const Axes& L, int ia, int ib, int ip) {
  const double la = L[static_cast<std::size_t>(ia)], lb = L[static_cast<std::size_t>(ib)];
  const double lp = L[static_cast<std::size_t>(ip)];
  const double across = std::sqrt(la * la + lb * lb), size = std::sqrt(across * across + lp * lp);
  const auto [ct, st] = half(lp / size, across / size);
  const auto [cp, sp] = half(lb / across, la / across);
  Axes v{};
  v[static_cast<std::size_t>(ia)] = st * cp;
  v[static_cast<std::size_t>(ib)] = -st * sp;
  v[static_cast<std::size_t>(ip)] = ct * sp;
  return {ct * cp, v[0], v[1], v[2]};
}

}  // namespace

JacobiElliptic jacobiElliptic(double u, double m) {
  if (m <= 0.0) return {std::sin(u), std::cos(u), 1.0, u};
  // The arithmetic-geometric mean of 1 and k' = sqrt(1 - m), keeping each
  // c_n = (a_{n-1} - b_{n-1}) / 2; it converges quadratically.
  constexpr int kMaxMeans = 24;
  std::array<double, kMaxMeans + 1> a{}, c{};
  a[0] = 1.0;
  c[0] = std::sqrt(m);
  double b = std::sqrt(1.0 - m);
  int n = 0;
  while (n < kMaxMeans && std::abs(c[static_cast<std::size_t>(n)]) > 1e-16 * a[static_cast<std::size_t>(n)]) {
    const double an = a[static_cast<std::size_t>(n)];
    a[static_cast<std::size_t>(n) + 1] = 0.5 * (an + b);
    c[static_cast<std::size_t>(n) + 1] = 0.5 * (an - b);
    b = std::sqrt(an * b);
    ++n;
  }
  // The amplitude back down the means: phi_{n-1} = (phi_n + asin(c_n / a_n sin phi_n)) / 2.
  double phi = std::ldexp(a[static_cast<std::size_t>(n)] * u, n);
  for (int i = n; i > 0; --i) {
    const auto at = static_cast<std::size_t>(i);
    phi = 0.5 * (phi + std::asin(c[at] / a[at] * std::sin(phi)));
  }
  const double sn = std::sin(phi), cn = std::cos(phi);
  // dn^2 = 1 - m sn^2 = cn^2 + (1 - m) sn^2, which keeps its digits near m = 1.
  return {sn, cn, std::sqrt(cn * cn + (1.0 - m) * sn * sn), phi};
}

double FreeRotation::energy(const Vec3& w) const {
  return 0.5 * (moments.x * w.x * w.x + moments.y * w.y * w.y + moments.z * w.z * w.z);
}

Vec3 FreeRotation::momentum(const Vec3& w) const { return {moments.x * w.x, moments.y * w.y, moments.z * w.z}; }

void FreeRotation::advance(Quat& q, Vec3& bodySpin, double dt) const {
  const Axes I = axes(moments);
  Axes w = axes(bodySpin);
  const Axes L = axes(momentum(bodySpin));
  // At rest, or spinning about one principal axis: the spin stays as it is.
  const int still = static_cast<int>(std::count(L.begin(), L.end(), 0.0));
  if (still == 3) return;
  if (still == 2) {
    const int j = L[0] != 0.0 ? 0 : (L[1] != 0.0 ? 1 : 2);
    q = (q * Quat::about(unit(j), w[static_cast<std::size_t>(j)] * dt)).normalized();
    return;
  }
  const auto at = [](int i) { return static_cast<std::size_t>(i); };
  std::array<int, 3> order{0, 1, 2};
  const auto swapIfAbove = [&](int i, int j) {
    if (I[at(order[at(i)])] > I[at(order[at(j)])]) std::swap(order[at(i)], order[at(j)]);
  };
  swapIfAbove(0, 1);
  swapIfAbove(1, 2);
  swapIfAbove(0, 1);
  const double low = I[at(order[0])], mid = I[at(order[1])], high = I[at(order[2])];
  const bool lowPair = mid - low <= kEqualMoments * high, highPair = high - mid <= kEqualMoments * high;
  if (lowPair && highPair) {  // a sphere's moments: the spin is fixed in the body and the world
    symmetricTop(0, I[0], I[0], q, w, L, dt);
    bodySpin = vec(w);
    return;
  }
  if (lowPair || highPair) {
    const int s = lowPair ? order[2] : order[0];
    symmetricTop(s, I[at(s)], lowPair ? 0.5 * (low + mid) : 0.5 * (mid + high), q, w, L, dt);
    bodySpin = vec(w);
    return;
  }
  // The axis the spin circles (p): the largest moment's when L^2 >= 2 T I_mid,
  // else the smallest's; q the other end, m the middle. The middle spin is
  // reflected where (q, m, p) is not cyclic or I_p < I_m, which puts Euler's
  // equations in the form whose solution is (A_q cn, s A_m sn, s A_p dn).
  const auto sq = [](double v) { return v * v; };
  const double across = sq(L[at(order[0])]) * (low - mid) / low + sq(L[at(order[2])]) * (high - mid) / high;
  const int iq = across >= 0 ? order[0] : order[2], im = order[1], ip = across >= 0 ? order[2] : order[0];
  const double Iq = I[at(iq)], Im = I[at(im)], Ip = I[at(ip)];
  const double reflect = (im == (iq + 1) % 3 ? 1.0 : -1.0) * (Ip > Im ? 1.0 : -1.0);
  const double wq = w[at(iq)], wm = reflect * w[at(im)], wp = w[at(ip)];
  // Amplitudes, rate and parameter, each a sum of terms of one sign (no
  // cancellation): D_q = L^2 - 2 T I_q, D_p = 2 T I_p - L^2.
  const double Aq = std::sqrt(sq(wq) + sq(wm) * Im * (Ip - Im) / (Iq * (Ip - Iq)));
  const double Am = std::sqrt(sq(wq) * Iq * (Ip - Iq) / (Im * (Ip - Im)) + sq(wm));
  const double Ap = std::sqrt(sq(wm) * Im * (Im - Iq) / (Ip * (Ip - Iq)) + sq(wp));
  const double Dq = sq(L[at(im)]) * (Im - Iq) / Im + sq(L[at(ip)]) * (Ip - Iq) / Ip;
  const double Dp = sq(L[at(iq)]) * (Ip - Iq) / Iq + sq(L[at(im)]) * (Ip - Im) / Im;
  const double rate = std::sqrt((Ip - Im) * Dq / (Iq * Im * Ip));
  const double m = std::min((Im - Iq) * Dp / ((Ip - Im) * Dq), kLargestParameter);
  const double s = wp >= 0 ? 1.0 : -1.0;
  // From sn, cn, dn now, by their addition theorem, a node at a time: the
  // spin at the step's end and, by Boole's rule over the nodes, the
  // integral of 1 / (1 - nu sn^2) that the turn about L needs.
  const double nu = -Ip * (Im - Iq) / (Iq * (Ip - Im));
  const double span = rate * dt;
  const int nodes = 4 * std::max(1, static_cast<int>(std::ceil(span / (4 * kNodeSpacing))));
  const double h = span / nodes;
  const JacobiElliptic step = jacobiStep(h, m);
  double sn = s * wm / Am, cn = wq / Aq, dn = s * wp / Ap;
  const auto f = [&] { return 1.0 / (1.0 - nu * sn * sn); };
  double sum = 7.0 * f();
  for (int i = 1; i <= nodes; ++i) {
    const double den = 1.0 - m * sn * sn * step.sn * step.sn;
    const double sn1 = (sn * step.cn * step.dn + step.sn * cn * dn) / den;
    const double cn1 = (cn * step.cn - sn * dn * step.sn * step.dn) / den;
    const double dn1 = (dn * step.dn - m * sn * cn * step.sn * step.cn) / den;
    sn = sn1, cn = cn1, dn = dn1;
    sum += (i == nodes ? 7.0 : (i % 2 == 1 ? 32.0 : (i % 4 == 2 ? 12.0 : 14.0))) * f();
  }
  const double integral = sum * 2.0 * h / 45.0;
  // Back on sn^2 + cn^2 = 1 and dn^2 + m sn^2 = 1, where the invariants are.
  const double r = std::sqrt(sn * sn + cn * cn);
  sn /= r, cn /= r;
  dn = std::sqrt(cn * cn + (1.0 - m) * sn * sn);
  w[at(iq)] = Aq * cn;
  w[at(im)] = reflect * s * Am * sn;
  w[at(ip)] = s * Ap * dn;
  // The body turns so that R L_body stays L_world: with Euler angles
  // (psi, theta, phi) about the momentum, p and the axis a after it, L_body
  // gives theta and phi at each end, and psi' = |L| / I_p + |L| (1/I_q -
  // 1/I_p) / (1 - nu sn^2), whose integral over the step (an elliptic
  // integral of the third kind) Boole's rule gave above.
  const double size = std::sqrt(sq(L[0]) + sq(L[1]) + sq(L[2]));
  const double turn = size * dt / Ip + size * (1.0 / Iq - 1.0 / Ip) / rate * integral;
  const int ia = (ip + 1) % 3, ib = (ip + 2) % 3;
  const Axes L1{I[0] * w[0], I[1] * w[1], I[2] * w[2]};
  const Quat start = towardsMomentum(L, ia, ib, ip), end = towardsMomentum(L1, ia, ib, ip);
  q = (q * start.conjugate() * Quat::about(unit(ip), turn) * end).normalized();
  bodySpin = vec(w);
}

}  // namespace tabletop
