#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "core/Integrator.h"
#include "core/SimulationMode.h"

namespace CLI {
class App;
}

namespace tabletop {

/// What `tabletop bench` was asked to do.
struct BenchOptions {
  std::vector<std::string> scenarios;  ///< scene files; default: the analytic cases and the report's examples
  std::string scenarioDir;  ///< --scenarios: where the default scenes are; empty: the shipped ones
  std::optional<std::string> cases;    ///< --cases: only scenes whose name contains this
  std::optional<std::string> outDir;   ///< --out: CSV and plots
  std::optional<std::string> frontFile;  ///< --write-front: the analytic cases' fronts, for run --tolerance
  bool json = false;
  int repeats = 5;                     ///< timed runs per setting, after one warm-up
  int jobs = 0;                        ///< worker processes timing the sweep's settings; 0: every core
  std::vector<double> rates{30, 60, 120, 240, 480, 1000, 2000, 4000};  ///< Hz
  std::vector<int> iterations{4, 10, 20, 50};
  std::vector<Integrator> integrators{Integrator::Euler, Integrator::Trapezoid};
  /// --modes: bullet sweeps the whole grid; compat and rules, the cheap
  /// end, sweep the rates at the scene's own iterations and integrator.
  std::vector<SimulationMode> modes{SimulationMode::Bullet, SimulationMode::Compat, SimulationMode::Rules};
  /// Sections: the sweep, the model switches on each scene, the cube field
  /// at these sizes. With none asked for, the sweep alone; asking for
  /// --switches or --scale leaves the sweep out unless --sweep is given.
  bool sweep = false;
  bool switches = false;
  std::vector<int> scale;
  std::vector<int> piles;    ///< bodies per pile (--piles)
  double pileBudget = 120;   ///< s of wall time per pile's tabletop run
  std::optional<int> threads;  ///< --threads (else TABLETOP_THREADS, else every core): the piles' second run
  bool hard = false;  ///< --hard: run every scene in SCENARIOS/hard once and measure its stability
  bool laws = false;  ///< --laws: the sliding, rolling, step, spinning and bouncing laws over shapes and supports
  bool baseline = false;  ///< --baseline: each scene's cost against Bullet's own default pipeline
};

/// Declares bench's options on `command`.
void addBenchOptions(CLI::App& command, BenchOptions& options);

/// Sweeps every scene over the timesteps and solver iterations: for each
/// setting, the median wall time per simulated second of `repeats` runs
/// (after a warm-up, with the spread) and the error (against the closed
/// form, or against a run at 4000 Hz and 50 iterations). Prints a table
/// per scene with its Pareto front of cost and error; with --out-dir writes
/// DIR/bench.csv and a log-log plot of error against cost per scene
/// (DIR/bench_SCENE.png, one curve per iteration count). Ctrl-C stops the
/// sweep, keeps what was measured and writes it (status 130).
///
/// --switches measures each model switch (ModelSwitch) on every scene at
/// its own settings: cost, error, and whether the outcome is bit-identical
/// to the defaults'. --scale N,... runs the cube field (CubeField) of each
/// size with each switch: wall time per step, and the growth exponent of
/// time against the number of cubes. --piles N,... drops a pile (Pile) of
/// each size in tabletop and in Bullet's own pipeline (measurePiles).
int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tabletop
