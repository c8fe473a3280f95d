#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/RunResult.h"
#include "core/SimulationMode.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// One quantity of an analytic case: its closed form and what a run gave.
struct AnalyticMeasure {
  std::string quantity;  ///< e.g. "A distance slid"
  std::string unit;      ///< "m" or "m/s"
  double truth = 0.0;
  double measured = 0.0;
  double error() const;  ///< |measured - truth|
};

/// The outcome of running an analytic case.
struct AnalyticResult {
  std::vector<AnalyticMeasure> measures;
  double positionError = 0.0;  ///< the largest error of the "m" measures, metres
  RunResult run;
};

/// A scenario whose outcome has a closed form (scenarios/analytic/): the
/// truth is computed here from the scenario's own parameters (masses,
/// materials combined as Bullet combines them, the push, g), so editing a
/// file changes its truth too. Cases are known by the scenario's name:
///  - cube_slides_to_rest: d = v0^2 / (2 mu g);
///  - sphere_slip_to_roll: slips until v1 = 5/7 v0 at t1 = 2 v0 / (7 mu g),
///    then rolls: x(T) = v0 t1 - mu g t1^2 / 2 + v1 (T - t1), v(T) = v1;
///  - free_flight: x = x0 + v T, y = y0 - g T^2 / 2;
///  - projectile_off_the_edge: first touches the floor at
///    x = edge + v sqrt(2 h / g), h the fall of the centre;
///  - head_on_spheres: vA = (mA - e mB) v / (mA + mB),
///    vB = (1 + e) mA v / (mA + mB), and where each stands at T;
///  - cube_tips_off_the_edge (report 3.4): a cube gliding slowly without
///    friction starts to tip when its centre passes the edge, and ends
///    resting on the floor;
///  - stack_rides_along, stack_rider_slips: a pushed cube carrying another;
///    the rider slips back until both move as one, then rides along if the
///    table slows the pair by less than mu g between them, else slips on
///    (see stackTravel in the source for the distances);
///  - straight_line_transfer (report 3.7): A pushed a step into B; B goes
///    on for the rest of the step, and A moves the whole step by the rule
///    (rules, compat) or stops where it met B (bullet, elastic cubes).
class AnalyticCase {
 public:
  /// The case of `scenario`, or nothing if its name is not one.
  static std::optional<AnalyticCase> forScenario(const Scenario& scenario);
  /// Every case's name.
  static std::vector<std::string> names();
  /// The kind of motion the case named `name` stands for (see motionsOf in
  /// ToleranceFront.h), or "" for an unknown name.
  static std::string motion(const std::string& name);

  const std::string& name() const { return name_; }
  /// Runs the scenario in `mode` with `settings` and compares.
  AnalyticResult run(const Scenario& scenario, const Settings& settings, SimulationMode mode) const;

 private:
  explicit AnalyticCase(std::string name) : name_(std::move(name)) {}
  std::string name_;
};

}  // namespace tabletop
