#include "sim/ScriptRunner.h"

#include <chrono>

#include "core/StateHash.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {

RunResult runScript(const Scenario& scenario, const Settings& settings, Simulation& sim,
                    const StepObserver& afterStep) {
  const auto start = std::chrono::steady_clock::now();
  ScriptPlayer player(scenario, settings, sim, afterStep);
  RunResult r;
  try {
    player.runToEnd();
  } catch (const DivergenceError& e) {
    r.complete = false;
    r.failure = e.what();
  }

  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.scenario = scenario.name;
  r.file = scenario.file;
  r.mode = std::string(sim.modeName());
  r.settings = settings;
  r.simTime = sim.time();
  r.steps = sim.steps();
  r.entities = sim.snapshot();
  r.events = sim.events();
  r.stateHash = stateHash(r.entities);
  r.solverUse = sim.solverUse();
  return r;
}

}  // namespace tabletop
