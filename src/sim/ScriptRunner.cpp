#include "sim/ScriptRunner.h"

#include <chrono>

#include "core/StateHash.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {

RunResult runScript(const Scenario& scenario, const Settings& settings, Simulation& sim,
                    const StepObserver& afterStep) {
  const auto start = std::chrono::steady_clock::now();
  ScriptPlayer player(scenario, settings, sim, afterStep);
  bool complete = true;
  std::string failure;
  try {
    player.runToEnd();
  } catch (const DivergenceError& e) {
    complete = false;
    failure = e.what();
  }
  RunResult r = outcomeNow(scenario, settings, sim);
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.complete = complete;
  r.failure = failure;
  return r;
}

RunResult outcomeNow(const Scenario& scenario, const Settings& settings, const Simulation& sim) {
  RunResult r;
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
  r.work = sim.work();
  return r;
}

}  // namespace tabletop
