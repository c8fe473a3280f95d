#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/Settings.h"
#include "core/SimulationMode.h"
#include "core/Vec3.h"
#include "scenario/Scenario.h"
#include "sim/AnalyticCase.h"

namespace tabletop {

/// A scene the bench measures: an analytic case (its error against the
/// closed form) or any other scenario (its error against a reference run
/// at the finest settings, kReferenceTimestep and kReferenceIterations,
/// with the trapezoid integrator).
class BenchScene {
 public:
  static constexpr double kReferenceTimestep = 1.0 / 4000.0;
  static constexpr int kReferenceIterations = 50;

  explicit BenchScene(Scenario scenario);

  const Scenario& scenario() const { return scenario_; }
  const std::string& name() const { return scenario_.name; }
  bool analytic() const { return analytic_.has_value(); }

  /// Runs once with `settings`; the error in metres (the largest position
  /// error) and the wall seconds the run took.
  struct Run {
    double error = 0.0;
    double wallSeconds = 0.0;
    double simSeconds = 0.0;
    bool complete = true;
  };
  Run run(const Settings& settings, SimulationMode mode = SimulationMode::Bullet);

 private:
  Scenario scenario_;
  std::optional<AnalyticCase> analytic_;
  std::optional<std::vector<Vec3>> reference_;  // final centres at the finest settings
};

/// One setting of the sweep, measured.
struct BenchPoint {
  std::string scene;
  double timestep = 0.0;  ///< s
  int iterations = 0;
  Integrator integrator = Integrator::Trapezoid;
  SimulationMode mode = SimulationMode::Bullet;
  double costMs = 0.0;    ///< median wall milliseconds per simulated second
  double spread = 0.0;    ///< (slowest - fastest) / median of the repeats
  double error = 0.0;     ///< m
  bool complete = true;
  bool front = false;     ///< on the scene's Pareto front of cost and error
};

/// Marks, among the points of each scene, those no other point beats in
/// both cost and error (the Pareto front).
void markParetoFronts(std::vector<BenchPoint>& points);

}  // namespace tabletop
