#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "core/ContactSolver.h"
#include "core/Settings.h"
#include "scenario/Scenario.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {

/// What a hard case is judged by: one full-physics run of a scenario,
/// watched after every step. SI units.
struct StabilityReport {
  double worstDrift = 0.0;        ///< m: farthest any entity's centre got from its start
  double worstPenetration = 0.0;  ///< m: deepest contact at the end of any step
  double restSpeed = 0.0;         ///< m/s: fastest any entity moved in the run's last second (last half if shorter)
  /// J: the largest rise of the mechanical energy (kinetic, rotational and
  /// potential above the floor) over its lowest value since the last push.
  double energyGain = 0.0;
  /// J: the largest excess of the mechanical energy over its value just
  /// after the last push (or at the start): energy the scene was never given.
  double energyExcess = 0.0;
  double energyScale = 0.0;  ///< J: the largest mechanical energy seen, for relative gains
  /// m: the lowest any entity's bottom came relative to the table top while
  /// its centre was over the top (negative: below it); +inf if none was.
  double lowestOverTop = std::numeric_limits<double>::infinity();
  /// m: the lowest any entity's bottom came relative to the floor (y = 0).
  double lowestOverFloor = std::numeric_limits<double>::infinity();
  /// m: the farthest any entity's centre got from the table's centre,
  /// measured along the floor.
  double farthest = 0.0;
  bool complete = true;   ///< false if the divergence guard stopped the run
  std::string failure;    ///< the guard's message when not complete
  long steps = 0;
  std::uint64_t stateHash = 0;  ///< the state at the end (core/StateHash.h)
  SolverUse solverUse;       ///< how the islands were solved over the run
  double simulated = 0.0;    ///< s
  double wallSeconds = 0.0;  ///< s, the stepping alone
  /// Milliseconds of wall time per simulated second.
  double cost() const { return simulated > 0 ? 1e3 * wallSeconds / simulated : 0.0; }
};

/// Runs `scenario` in full physics at `settings` to its end (the script,
/// the duration, rest when settings.endAtRest) and measures it. `afterStep`
/// sees the simulation after every step as well.
StabilityReport probeStability(const Scenario& scenario, const Settings& settings,
                               const StepObserver& afterStep = {});

}  // namespace tabletop
