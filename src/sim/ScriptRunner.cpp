#include "sim/ScriptRunner.h"

#include <chrono>
#include <stdexcept>

#include "core/StateHash.h"
#include "scenario/ScenarioError.h"

namespace tabletop {
namespace {

// Times within this of a target count as reached (steps accumulate rounding).
constexpr double kTimeSlack = 1e-9;

class Stepper {
 public:
  Stepper(Simulation& sim, double duration, const StepObserver& observer)
      : sim_(sim), duration_(duration), observer_(observer) {}

  bool canStep() const { return sim_.time() < duration_ - kTimeSlack; }
  void until(double t) {
    while (sim_.time() < t - kTimeSlack && canStep()) advance();
  }
  void untilRest(double deadline) {
    while (!sim_.allAtRest() && sim_.time() < deadline - kTimeSlack && canStep()) advance();
  }

 private:
  void advance() {
    sim_.step();
    if (observer_) observer_(sim_);
  }

  Simulation& sim_;
  double duration_;
  const StepObserver& observer_;
};

}  // namespace

RunResult runScript(const Scenario& scenario, const Settings& settings, Simulation& sim,
                    const StepObserver& afterStep) {
  const auto start = std::chrono::steady_clock::now();
  Stepper stepper(sim, settings.duration, afterStep);

  for (const Action& action : scenario.script) {
    if (action.at) stepper.until(*action.at);
    if (!stepper.canStep() && action.type != Action::Type::WaitRest) break;
    try {
      switch (action.type) {
        case Action::Type::Push: sim.push(action.arrow, action.magnitude); break;
        case Action::Type::Rotate: sim.rotate(action.entity, action.degrees); break;
        case Action::Type::WaitTime: stepper.until(sim.time() + action.seconds); break;
        case Action::Type::WaitRest:
          stepper.untilRest(action.seconds > 0 ? sim.time() + action.seconds : settings.duration);
          break;
      }
    } catch (const std::invalid_argument& e) {
      throw ScenarioError(scenario.file, {{action.path, std::string("cannot do this action in mode ") +
                                                            std::string(sim.modeName()) + ": " + e.what()}});
    }
  }
  if (settings.endAtRest) {
    stepper.untilRest(settings.duration);
  } else {
    stepper.until(settings.duration);
  }

  RunResult r;
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
  return r;
}

}  // namespace tabletop
