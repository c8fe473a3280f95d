#pragma once

#include <cstdint>
#include <string>

#include "measure/StabilityProbe.h"

namespace tabletop {

/// One of the random stability runs (hard case 9): RandomScene's scene for
/// a seed, run in full physics at the default settings but the step, and
/// judged. SI units. A run is stable when it:
///  - finishes (the divergence guard finds every state finite and within
///    what the scene's energy allows);
///  - keeps every body in the world: never wholly under the floor (its
///    highest point below it: it has passed through), and never further
///    from the table's centre than the table's half-diagonal plus the
///    distance the fastest speed its energy allows, sqrt(2 E_max / m_min),
///    covers in the run;
///  - never holds more mechanical energy than it was last given, beyond
///    kExcessShare of the largest energy seen (the penetration split
///    impulse takes out lifts bodies a little);
///  - never gains more than kGainShare over its lowest energy since the
///    last push (the same lift counted from a body's deepest landing).
/// docs/hard-cases.md gives the figures measured against these bounds.
struct RandomRunCheck {
  static constexpr double kExcessShare = 0.001;
  static constexpr double kGainShare = 0.015;

  std::uint64_t seed = 0;
  int bodies = 0;
  int pushes = 0;
  StabilityReport report;
  double underFloor = 0.0;  ///< m: how far a body's highest point went under the floor (0: never)
  double reach = 0.0;       ///< m: the farthest a centre may get from the table's centre
  std::string reason;       ///< why the run is not stable; empty when it is

  bool stable() const { return reason.empty(); }
};

/// Runs and judges the scene of `seed` at a step of `timestep` s (0: the
/// default settings' step). `afterStep` sees every step and may throw to
/// stop the run.
RandomRunCheck checkRandomRun(std::uint64_t seed, double timestep, const StepObserver& afterStep = {});

}  // namespace tabletop
