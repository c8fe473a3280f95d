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
#include "scenario/Scenario.h"
#include "sim/ScriptPlayer.h"

namespace tabletop::python {

/// A scene stepped from Python: the scenario it owns, the simulation in one
/// mode, and the script player that carries out its script (none when
/// asked for) and guards against divergence. Plain C++, free of Python:
/// the binding checks every argument first and calls it with the GIL
/// released, one thread at a time (SimulationObject).
class SteppedScene {
 public:
  SteppedScene(Scenario scenario, SimulationMode mode, bool script);

  /// `n` steps; `between` runs after each (the check for Ctrl-C).
  void step(long long n, const std::function<void()>& between);
  /// Steps until finished(), at most to the duration the loader bounded.
  void runToEnd(const std::function<void()>& between);
  void push(const Arrow& arrow, const PushMagnitude& magnitude) { player_->push(arrow, magnitude); }
  void rotate(const std::string& entity, double degrees) { simulation_->rotate(entity, degrees); }

  /// The scene now, drawn headless: width x height RGB, top row first.
  Image render(int width, int height, const CameraChoice& camera, bool arrow) const;
  RunResult result() const;

  const Scenario& scenario() const { return *scenario_; }
  const Simulation& simulation() const { return *simulation_; }
  bool finished() const { return player_->finished(); }

 private:
  std::unique_ptr<Scenario> scenario_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<ScriptPlayer> player_;
  // The last render's context, kept for the next of the same size: making
  // one cost 20-50 ms, more than the frame.
  mutable std::unique_ptr<HeadlessFrames> frames_;
};

}  // namespace tabletop::python
