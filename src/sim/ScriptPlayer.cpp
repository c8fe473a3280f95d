#include "sim/ScriptPlayer.h"

#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "scenario/ScenarioError.h"

namespace tabletop {
namespace {

// Times within this of a target count as reached (steps accumulate rounding).
constexpr double kTimeSlack = 1e-9;

}  // namespace

ScriptPlayer::ScriptPlayer(const Scenario& scenario, const Settings& settings, Simulation& simulation,
                           StepObserver afterStep)
    : scenario_(scenario),
      settings_(settings),
      simulation_(simulation),
      afterStep_(std::move(afterStep)),
      guard_(scenario, settings, simulation.motions()),
      workStart_(simulation.work().units()) {}

bool ScriptPlayer::durationReached() const {
  return simulation_.time() >= settings_.duration - kTimeSlack;
}

bool ScriptPlayer::waiting() const {
  if (durationReached()) return false;
  switch (wait_) {
    case Wait::None: return false;
    case Wait::Until: return simulation_.time() < deadline_ - kTimeSlack;
    case Wait::UntilRest: return !simulation_.allAtRest() && simulation_.time() < deadline_ - kTimeSlack;
  }
  return false;
}

// The pushes due together are checked against the guard together: one
// look at every body before them and one after, not two per push, which
// made a script pushing each of n entities cost O(n^2). The energy they
// add together is no more than the sum of what each adds alone.
void ScriptPlayer::runDue() {
  const std::vector<Action>& script = scenario_.script;
  std::optional<std::vector<BodyMotion>> beforePushes;
  while (!waiting()) {
    wait_ = Wait::None;
    if (next_ >= script.size()) break;
    const Action& action = script[next_];
    if (action.at && !startTimeMet_) {
      startTimeMet_ = true;
      wait_ = Wait::Until;
      deadline_ = *action.at;
      continue;
    }
    startTimeMet_ = false;
    ++next_;
    if (durationReached()) {
      // Past the duration only a wait for rest may still "run" (as a no-op).
      if (action.type != Action::Type::WaitRest) next_ = script.size();
      continue;
    }
    if (action.type == Action::Type::Push && !beforePushes) beforePushes = simulation_.motions();
    carryOut(action);
  }
  if (beforePushes) guard_.pushed(*beforePushes, simulation_.motions());
}

void ScriptPlayer::carryOut(const Action& action) {
  try {
    switch (action.type) {
      case Action::Type::Push: applyPush(action.arrow, action.magnitude); break;
      case Action::Type::Rotate: simulation_.rotate(action.entity, action.degrees); break;
      case Action::Type::WaitTime:
        wait_ = Wait::Until;
        deadline_ = simulation_.time() + action.seconds;
        break;
      case Action::Type::WaitRest:
        wait_ = Wait::UntilRest;
        deadline_ = action.seconds > 0 ? simulation_.time() + action.seconds : settings_.duration;
        break;
    }
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(scenario_, {{action.path, std::string("cannot do this action in mode ") +
                                                           std::string(simulation_.modeName()) + ": " +
                                                           e.what()}});
  }
}

void ScriptPlayer::push(const Arrow& arrow, const PushMagnitude& magnitude) {
  const std::vector<BodyMotion> before = simulation_.motions();
  applyPush(arrow, magnitude);
  guard_.pushed(before, simulation_.motions());
}

void ScriptPlayer::applyPush(const Arrow& arrow, const PushMagnitude& magnitude) {
  simulation_.push(arrow, magnitude);
  lastArrow_ = arrow;
  ++pushes_;
}

std::optional<Arrow> ScriptPlayer::arrow() const {
  if (lastArrow_) return lastArrow_;
  for (const Action& a : scenario_.script) {
    if (a.type == Action::Type::Push) return a.arrow;
  }
  return std::nullopt;
}

void ScriptPlayer::step() {
  simulation_.step();
  checkWork();
  guard_.check(simulation_.motions(), simulation_.time());
  if (afterStep_) afterStep_(simulation_);
  runDue();
}

void ScriptPlayer::checkWork() const {
  const double done = simulation_.work().units() - workStart_;
  if (done <= workLimit_) return;
  std::ostringstream message;
  message << "expected at most " << workLimit_ << " units of work in one run (about 10 minutes of one core; "
          << "docs/limits.md), stopped at t = " << simulation_.time() << " s after " << done
          << ": shorten the duration, or use fewer bodies or iterations";
  throw ScenarioError(scenario_, {{"/settings/duration", message.str()}});
}

bool ScriptPlayer::finished() const {
  if (durationReached()) return true;
  return scriptDone() && settings_.endAtRest && simulation_.allAtRest();
}

void ScriptPlayer::runToEnd() {
  runDue();
  while (!finished()) step();
}

}  // namespace tabletop
