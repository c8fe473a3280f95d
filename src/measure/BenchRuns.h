#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/Integrator.h"
#include "core/Settings.h"
#include "core/SimulationMode.h"
#include "measure/Benchmark.h"
#include "measure/PlainBullet.h"
#include "measure/StabilityProbe.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// How a long measurement reports its progress and is stopped: `stop` is
/// asked before each unit of work, `start` told how many there are,
/// `advance` told of each one done. The defaults do nothing, so a test or
/// the Python module can measure without a terminal.
struct MeasureHooks {
  std::function<bool()> stop = [] { return false; };
  std::function<void(long total)> start = [](long) {};
  std::function<void(const std::string& done)> advance = [](const std::string&) {};
};

/// The settings `bench` sweeps: every rate, and in full physics every
/// iteration count and integrator too.
struct SweepGrid {
  std::vector<double> rates;  ///< Hz
  std::vector<int> iterations;
  std::vector<Integrator> integrators;
};

/// Sweeps every scene in every mode of `modes` over the grid: each setting
/// timed `repeats` times after a warm-up. A mode a scene cannot run in is
/// skipped, with why, in `skipped` (per scene). With `jobs` > 1 the
/// settings are timed on that many worker processes at once, one setting
/// each, so each timing still runs on one core; the points are the same,
/// in the same order, but for the timings.
std::vector<BenchPoint> measureSweep(std::vector<BenchScene>& scenes, const SweepGrid& grid,
                                     const std::vector<SimulationMode>& modes, int repeats, const MeasureHooks& hooks,
                                     std::map<std::string, std::vector<std::string>>& skipped, int jobs = 1);

/// Each model switch (ModelSwitch) on every scene at its own settings.
std::vector<SwitchPoint> measureSwitches(std::vector<BenchScene>& scenes, int repeats, const MeasureHooks& hooks);

/// The cube field (CubeField) of each size with each switch.
std::vector<ScalePoint> measureScale(const std::vector<int>& sizes, int repeats, const MeasureHooks& hooks);

/// The growth exponent of each switch's time per step over the sizes.
std::map<std::string, double> exponents(const std::vector<ScalePoint>& points);

/// A scene at one rate, at its own settings otherwise, against the same
/// scene in Bullet's own default pipeline (PlainBullet) for as long as
/// tabletop's run simulated. A scene full physics refuses gets no point.
struct BaselinePoint {
  std::string scene;
  double rate = 0;           ///< Hz
  double tabletopMs = 0;     ///< median wall ms per simulated second
  double bulletMs = 0;       ///< likewise, Bullet's own pipeline
  double simulated = 0;      ///< s
};

std::vector<BaselinePoint> measureBaseline(std::vector<BenchScene>& scenes, const std::vector<double>& rates,
                                           int repeats, const MeasureHooks& hooks);

/// The drift a peer reaches on a resting hard case, m: MuJoCo 2.2.2 at its
/// defaults holds the ten-cube stack to 0.7 mm over 60 s at 120 Hz, for
/// about 8 ms per simulated second (at 60 Hz it drifts 16 mm). A resting
/// case's cost is compared with a peer's at this drift, not at a rate.
inline constexpr double kPeerDrift = 0.7e-3;

/// The rates a resting hard case is tried at below its own, from the
/// highest down, Hz: where a lower step still holds the drift, the same
/// accuracy costs fewer steps.
inline constexpr double kLowerRates[] = {120.0, 60.0, 30.0, 20.0, 15.0, 10.0};

/// A hard case at the lowest rate that still holds it to a drift.
struct DriftMatch {
  double rate = 0;         ///< Hz; 0 for a case with none (lowestRateHolding)
  StabilityReport report;  ///< the run at that rate (the scene's own run when it is the lowest)
};

/// The lowest of kLowerRates (or the scene's own rate) at which `scenario`,
/// at its own settings otherwise, keeps every centre within `drift` m of its
/// start and runs to its end: tried from the highest down, stopping at the
/// first rate that does not hold. `own` is the run at the scene's own rate;
/// a case it does not hold (one that moves, say), or a weightless one, gets
/// rate 0 and no more runs. Drift alone decides, so the rate found is the
/// same on every machine; the cost is whatever that run took.
DriftMatch lowestRateHolding(const Scenario& scenario, const StabilityReport& own, double drift);

/// One hard case, run once (docs/hard-cases.md).
struct HardPoint {
  std::string scene;
  Settings settings;
  StabilityReport report;  ///< at the scene's settings (the solver chosen per island by default)
  StabilityReport sweeps;  ///< the same with sequential impulses, kHardSweeps iterations
  PlainRun plain;          ///< the scene in Bullet's own default pipeline, same step and duration
  DriftMatch atPeerDrift;  ///< the lowest rate holding kPeerDrift, and its cost
};

/// The sweeps a hard case is also run with: Bullet's default count.
inline constexpr int kHardSweeps = 10;

/// Every scene in the folder `dir` (its .json files, by name) run once
/// and probed for stability, and again with sequential impulses at
/// kHardSweeps iterations and in Bullet's own default pipeline (one timed
/// run after a warm-up), and at the lowest rate that holds kPeerDrift.
/// Throws ScenarioError for a bad file.
std::vector<HardPoint> measureHard(const std::string& dir, const MeasureHooks& hooks);

}  // namespace tabletop
