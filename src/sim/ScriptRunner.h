#pragma once

#include <functional>

#include "core/RunResult.h"
#include "core/Simulation.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// Plays a scenario's script on a Simulation of any mode, then lets it run
/// until everything is at rest (when settings.endAtRest) or until the
/// duration ends, and collects the outcome.
///
/// Actions run in order. One with a time "t" first waits for that time;
/// "wait": "rest" steps until nothing moves (or its timeout); "wait": S
/// steps S seconds. Nothing runs past settings.duration. An action the mode
/// cannot carry out throws a ScenarioError naming the action.
///
/// `afterStep`, when given, sees the simulation after every step (the
/// comparison records trajectories with it).
using StepObserver = std::function<void(const Simulation&)>;
RunResult runScript(const Scenario& scenario, const Settings& settings, Simulation& simulation,
                    const StepObserver& afterStep = {});

}  // namespace tabletop
