#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/Settings.h"
#include "scenario/Scenario.h"
#include "measure/Benchmark.h"

namespace tabletop {

/// The kinds of motion a scene can hold, each stood for by analytic cases
/// (AnalyticCase::motion): flight, leaving the table, sliding, rolling,
/// collision, stacking.
std::vector<std::string> motionsOf(const Scenario& scene);

/// What `run --tolerance` chose, and why, one line per motion.
struct ToleranceChoice {
  Settings settings;
  std::vector<std::string> reasons;
  bool met = true;  ///< false when some motion cannot reach the tolerance at any measured setting
};

/// The bench's Pareto fronts of the analytic cases in full physics: for
/// each case, the settings no other setting beats in both cost and error.
/// It is shipped with the project (data/tolerance_front.json) and regenerated
/// by `tabletop bench --modes bullet --write-front data/tolerance_front.json`.
class ToleranceFront {
 public:
  struct Point {
    double timestep = 0.0;  ///< s
    int iterations = 0;
    Integrator integrator = Integrator::Trapezoid;
    double costMs = 0.0;    ///< wall ms per simulated second, on the machine that measured it
    double error = 0.0;     ///< m
  };

  /// The fronts of the analytic scenes among `points` (bullet mode only).
  static ToleranceFront fromBench(const std::vector<BenchPoint>& points);
  /// Reads a front file. Throws ScenarioError naming the file and place.
  static ToleranceFront load(const std::string& file);
  std::string toJson() const;

  /// The cheapest settings that meet `tolerance` (m) for every motion in
  /// `scene`: for each motion, each of its cases' cheapest front point
  /// within the tolerance; of those, the finest timestep and the most
  /// iterations, and the trapezoid integrator if any of them has it (Euler
  /// only gains where it ties: it is first order where the trapezoid rule
  /// is exact). Other settings (duration, gravity, ...) stay the scene's.
  ToleranceChoice choose(const Scenario& scene, double tolerance) const;

  const std::map<std::string, std::vector<Point>>& cases() const { return cases_; }

 private:
  std::map<std::string, std::vector<Point>> cases_;  // by case name, cheapest first
};

}  // namespace tabletop
