#pragma once

#include <string>

#include "core/Vec3.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// A cone (or a truncated cone) lying on its side and rolling on it, the
/// scene of the circle law: set rolling exactly at the start, it turns
/// about the vertical through its apex (a truncated cone's: where its
/// slant side's line meets the support) at the precession rate, its centre
/// of mass on a level circle about that point, forever (no rolling
/// resistance). Rolling, its spin lies along the line it touches the
/// support on; with a its half angle, a spin w about that line turns it
/// about the vertical at -w tan a.
struct RollCase {
  std::string support = "table";  ///< one of kLawSupports (LawScenes.h)
  double baseRadius = 0.05, topRadius = 0, height = 0.1;  ///< m, as a cylinder's "size"
  double precession = -2;  ///< rad/s about +y
  double rate = 60;        ///< Hz
};

inline constexpr double kRollDuration = 3.0;  ///< s

/// The scene: the body named "A", 1 kg, friction 1 on a support of
/// friction 1, its apex at the support's middle; for kRollDuration.
Scenario rollScene(const RollCase& c);

/// Where its centre of mass is at time t (s) in the closed form, m.
Vec3 rollCentre(const RollCase& c, double t);

/// The apex it turns about, m (on the support).
Vec3 rollApex(const RollCase& c);

/// The spin about its line of contact that gives the precession, rad/s.
double rollSpin(const RollCase& c);

/// "cone 0.05 / 0 x 0.1 on the table, precessing at -2 rad/s, 60 Hz".
std::string describe(const RollCase& c);

}  // namespace tabletop
