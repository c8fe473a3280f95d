#pragma once

#include "scenario/Scenario.h"
#include "core/Simulation.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop::test {

/// Builds `scenario` in `mode` with its own settings and runs its script to
/// its end: what a test that compares a whole run with a closed form needs.
inline RunResult runScene(const Scenario& scenario, SimulationMode mode = SimulationMode::Bullet) {
  auto simulation = buildSimulation(scenario, scenario.settings, mode);
  return runScript(scenario, scenario.settings, *simulation);
}

}  // namespace tabletop::test
