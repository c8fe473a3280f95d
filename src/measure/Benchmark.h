#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/Settings.h"
#include "core/SimulationMode.h"
#include "core/Vec3.h"
#include "scenario/Scenario.h"
#include "measure/AnalyticCase.h"

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
  /// Whether `settings` in `mode` are the reference run's own: its error
  /// is zero by construction, so it is neither plotted nor on the front.
  bool isReference(const Settings& settings, SimulationMode mode) const;

  /// Runs once with `settings`; the error in metres (the largest position
  /// error) and the wall seconds the run took.
  struct Run {
    double error = 0.0;
    double wallSeconds = 0.0;
    double simSeconds = 0.0;
    bool complete = true;
    std::uint64_t hash = 0;     ///< stateHash of the final state
    std::vector<Vec3> centres;  ///< every entity's final centre, m
  };
  Run run(const Settings& settings, SimulationMode mode = SimulationMode::Bullet);
  /// Whether run() still has to make the reference run (the first run of
  /// a scene that is not analytic makes it).
  bool needsReference() const { return !analytic_ && !reference_; }
  /// Makes the reference run: every entity's final centre, m.
  std::vector<Vec3> referenceCentres() const;
  /// The reference run's centres, made elsewhere (in another process).
  void setReference(std::vector<Vec3> centres) { reference_ = std::move(centres); }
  /// As run(), without the error (no reference run is made): for scenes
  /// too large to run at the reference settings.
  Run measure(const Settings& settings, SimulationMode mode = SimulationMode::Bullet);

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
  bool reference = false; ///< the settings of the scene's own reference run (error 0 by construction)
};

/// A model switch (ModelSwitch) measured on a scene, in full physics at
/// the scene's own settings.
struct SwitchPoint {
  std::string scene;
  std::string name;       ///< "defaults", "sleeping=on", ...
  double costMs = 0.0;    ///< median wall milliseconds per simulated second
  double spread = 0.0;
  double error = 0.0;     ///< m, as BenchPoint's
  bool sameState = true;  ///< the final state is bit-identical to the defaults'
  bool complete = true;
};

/// The cube field (CubeField) of one size with one model switch.
struct ScalePoint {
  int cubes = 0;
  std::string name;           ///< as SwitchPoint's
  double msPerStep = 0.0;     ///< median wall milliseconds per step
  double spread = 0.0;
  double difference = 0.0;    ///< m: the largest distance of a final centre from the defaults'
  bool sameState = true;
  bool complete = true;
};

/// The least-squares slope of log(y) against log(x): the exponent k of
/// y ~ x^k. Needs two distinct x at least; NaN otherwise.
double growthExponent(const std::vector<double>& x, const std::vector<double>& y);

/// Marks, among the points of each scene, those no other point beats in
/// both cost and error (the Pareto front); a scene's reference run is
/// neither on it nor beats anything.
void markParetoFronts(std::vector<BenchPoint>& points);

}  // namespace tabletop
