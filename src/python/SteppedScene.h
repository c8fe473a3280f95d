#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/RunResult.h"
#include "core/Simulation.h"
#include "core/SimulationMode.h"
#include "draw/CameraChoice.h"
#include "headless/HeadlessFrames.h"
#include "image/Image.h"
#include "python/SceneHistory.h"
#include "scenario/Scenario.h"
#include "sim/ScriptPlayer.h"

namespace tabletop::python {

/// A scene stepped from Python: the scenario it owns, the simulation in one
/// mode, and the script player that carries out its script (none when
/// asked for) and guards against divergence. Plain C++, free of Python:
/// the binding checks every argument first and calls it with the GIL
/// released, one thread at a time (SimulationObject).
///
/// Every call that changes the scene is kept in its history
/// (SceneHistory), so that reset() and restore() build it again bit for
/// bit.
class SteppedScene {
 public:
  SteppedScene(Scenario scenario, SimulationMode mode, bool script);

  /// `n` steps; `between` runs after each (the check for Ctrl-C).
  void step(long long n, const std::function<void()>& between);
  /// Steps until finished(), at most to the duration the loader bounded.
  void runToEnd(const std::function<void()>& between);
  void push(const Arrow& arrow, const PushMagnitude& magnitude);
  void rotate(const std::string& entity, double degrees);
  void applyImpulse(const std::string& entity, const Vec3& impulse, const std::optional<Vec3>& point);
  /// A force and torque on `entity` through the next step.
  void applyForce(const std::string& entity, const Vec3& force, const Vec3& torque, const std::optional<Vec3>& point);
  /// Steps from now on last `seconds`; scenario().settings says so.
  void setTimestep(double seconds);
  /// Gravity from now on, m/s^2 along -Y; scenario().settings says so.
  void setGravity(double g);

  /// The scene as it was built, its settings too; the history empties.
  void reset();
  /// The scene built again with `history`'s calls made on it: the state
  /// they made, bit for bit. Each call is checked as it was when made
  /// (std::invalid_argument for an unknown entity); the steps as a whole
  /// are held to the loader's bound on a run's size, and `between` runs
  /// after each step.
  void restore(const SceneHistory& history, const std::function<void()>& between);
  const SceneHistory& history() const { return history_; }
  /// Why the history cannot give back the state now (a step that raised,
  /// or too many calls), or empty when it can.
  std::string unsaveable() const;

  /// The scene now, drawn headless: width x height RGB, top row first. A
  /// fitted camera frames fittedExtent(), or with `fitNow` the scene now.
  /// With `bodies`, the same frame's bodies and depths (BodyImage) too.
  Image render(int width, int height, const CameraChoice& camera, bool arrow, bool fitNow = false,
               BodyImage* bodies = nullptr) const;
  /// What a fitted camera frames: the table and everything the scene's run
  /// reaches as its script plays it from the start to its end (found once,
  /// by running a copy, as render's first playback does), and the
  /// entities at `now`. A frame in a loop so keeps its camera.
  SceneExtent fittedExtent(const std::vector<EntityState>& now) const;
  RunResult result() const;

  const Scenario& scenario() const { return *scenario_; }
  const Simulation& simulation() const { return *simulation_; }
  SimulationMode mode() const { return mode_; }
  bool finished() const { return player_->finished(); }

 private:
  void build();
  void stepPlayer(long long n, const std::function<void()>& between);
  // What is wrong with replaying `history`'s steps, as the loader says it
  // of a run's (empty when nothing is).
  std::string tooLong(const SceneHistory& history) const;

  std::unique_ptr<Scenario> scenario_;
  Settings built_;  // the settings it was built with
  SimulationMode mode_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<ScriptPlayer> player_;
  SceneHistory history_;
  std::string failed_;  // what a step raised, once one did
  // The last render's context, kept for the next of the same size: making
  // one cost 20-50 ms, more than the frame.
  mutable std::unique_ptr<HeadlessFrames> frames_;
  mutable std::optional<SceneExtent> runExtent_;  // fittedExtent()'s run, once found
};

}  // namespace tabletop::python
