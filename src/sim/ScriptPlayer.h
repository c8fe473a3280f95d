#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include "core/Settings.h"
#include "core/Simulation.h"
#include "scenario/Scenario.h"
#include "sim/DivergenceGuard.h"

namespace tabletop {

/// Sees the simulation after every step (the comparison records
/// trajectories with it).
using StepObserver = std::function<void(const Simulation&)>;

/// Plays a scenario's script on a Simulation of any mode, one step at a
/// time, so that a batch run, a renderer taking frames and the interactive
/// viewer all carry out the same actions at the same simulated times.
///
/// Actions run in order. One with a time "t" first waits for that time;
/// "wait": "rest" waits until nothing moves (or its timeout, or the
/// duration); "wait": S waits S seconds. Once the duration is reached the
/// remaining pushes and rotations are dropped. An action the mode cannot
/// carry out throws a ScenarioError naming the action.
class ScriptPlayer {
 public:
  ScriptPlayer(const Scenario& scenario, const Settings& settings, Simulation& simulation,
               StepObserver afterStep = {});

  /// Carries out every action whose time has come, up to the first one
  /// that must wait.
  void runDue();
  /// One step of the simulation, then runDue(). Throws DivergenceError
  /// when a body leaves the bounds of the scene (see DivergenceGuard), and
  /// a ScenarioError located at the duration once the work since
  /// restartWorkCount() passes WorkCount::kRunLimit.
  void step();
  /// True when no action is left and none is waiting.
  bool scriptDone() const { return next_ >= scenario_.script.size() && wait_ == Wait::None; }
  /// True once a batch run ends: the duration is reached, or the script is
  /// done and (with settings.endAtRest) everything is at rest.
  bool finished() const;
  /// Steps until finished().
  void runToEnd();
  /// Counts the work limit (WorkCount::kRunLimit) from now: a run's is
  /// counted from its start, a stepping call's from the call.
  void restartWorkCount() { workStart_ = simulation_.work().units(); }
  /// The work limit, units; WorkCount::kRunLimit unless a test lowers it.
  void setWorkLimit(double units) { workLimit_ = units; }

  /// Pushes now, as a scripted push does (the viewer's pushes come here).
  /// Throws std::invalid_argument when the mode cannot.
  void push(const Arrow& arrow, const PushMagnitude& magnitude);
  /// The arrow of the last push, or before any push the first scripted
  /// push's arrow; empty if there is neither.
  std::optional<Arrow> arrow() const;
  /// Pushes so far, scripted or not.
  int pushes() const { return pushes_; }

  Simulation& simulation() { return simulation_; }

 private:
  enum class Wait { None, Until, UntilRest };
  bool durationReached() const;
  bool waiting() const;
  void checkWork() const;
  void carryOut(const Action& action);
  void applyPush(const Arrow& arrow, const PushMagnitude& magnitude);

  const Scenario& scenario_;
  Settings settings_;
  Simulation& simulation_;
  StepObserver afterStep_;
  std::size_t next_ = 0;     // the next action
  bool startTimeMet_ = false;  // the next action's "t" has been waited for
  Wait wait_ = Wait::None;
  double deadline_ = 0.0;
  std::optional<Arrow> lastArrow_;
  int pushes_ = 0;
  DivergenceGuard guard_;
  double workStart_ = 0.0;  // units, when the work limit's count began
  double workLimit_ = WorkCount::kRunLimit;
};

}  // namespace tabletop
