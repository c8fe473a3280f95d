#pragma once

#include "core/RunResult.h"
#include "core/Simulation.h"
#include "scenario/Scenario.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {

/// Plays a scenario's script on a Simulation of any mode (a ScriptPlayer)
/// until it is finished: the script done and everything at rest (when
/// settings.endAtRest), or the duration reached; then collects the outcome.
/// `afterStep`, when given, sees the simulation after every step. A run
/// that diverges stops there and comes back marked incomplete.
RunResult runScript(const Scenario& scenario, const Settings& settings, Simulation& simulation,
                    const StepObserver& afterStep = {});

/// The outcome of `simulation` as it is now (no wall time, complete): what
/// runScript returns, for a simulation stepped by other means.
RunResult outcomeNow(const Scenario& scenario, const Settings& settings, const Simulation& simulation);

}  // namespace tabletop
