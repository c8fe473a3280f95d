#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/EntityState.h"
#include "core/Event.h"
#include "core/Settings.h"
#include "core/WorkCount.h"

namespace tabletop {

/// The outcome of running one scenario in one mode: what `tabletop run`
/// prints, as text or JSON.
struct RunResult {
  std::string scenario;  ///< the scenario's name
  std::string file;      ///< where it was read from
  std::string mode;      ///< "bullet", ...
  Settings settings;
  double simTime = 0.0;  ///< seconds simulated
  long steps = 0;
  double wallSeconds = 0.0;
  std::vector<EntityState> entities;
  std::vector<Event> events;
  std::uint64_t stateHash = 0;
  SolverUse solverUse;  ///< how the contact islands were solved (full physics and compat)
  WorkCount work;       ///< what the run did, counted (WorkCount.h)
  /// False when the run stopped early (it diverged); `failure` says why,
  /// and the states are those at the last step checked.
  bool complete = true;
  std::string failure;
};

}  // namespace tabletop
