#include "measure/BenchRuns.h"
#include "measure/PlainBullet.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <utility>

#include "core/Broadphase.h"
#include "io/ProcessPool.h"
#include "measure/ModelSwitch.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "scenes/CubeField.h"
#include "sim/ResultFormat.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The settings to sweep for `scene` in `mode`: the whole grid in bullet
// mode; the rates alone in compat and rules, whose rules do not iterate.
std::vector<Settings> sweep(const SweepGrid& grid, const Scenario& scene, SimulationMode mode) {
  std::vector<Settings> out;
  for (double rate : grid.rates) {
    Settings s = scene.settings;
    s.timestep = 1.0 / rate;
    if (mode != SimulationMode::Bullet) {
      out.push_back(s);
      continue;
    }
    for (int it : grid.iterations) {
      for (Integrator integrator : grid.integrators) {
        s.iterations = it;
        s.integrator = integrator;
        out.push_back(s);
      }
    }
  }
  return out;
}

// Whether `scene` runs in `mode` (compat and rules move entities by steps
// only): the reason it does not, or nothing.
std::optional<std::string> refusal(const Scenario& scene, SimulationMode mode) {
  try {
    Settings quick = scene.settings;
    quick.duration = quick.timestep;
    auto simulation = buildSimulation(scene, quick, mode);
    runScript(scene, quick, *simulation);
  } catch (const ScenarioError& e) {
    return e.lines().empty() ? std::string("refused") : e.lines().front();
  }
  return std::nullopt;
}

// Runs `run` `repeats` times after a warm-up (when `warmUp`): the median
// and spread of the wall milliseconds per simulated second, and the last
// run.
struct Timed {
  double costMs = 0.0;
  double spread = 0.0;
  BenchScene::Run last;
};

template <class RunOnce>
Timed timed(int repeats, bool warmUp, double timestep, RunOnce runOnce) {
  Timed t;
  if (warmUp) runOnce();
  std::vector<double> costs;
  bool complete = true;
  for (int r = 0; r < repeats; ++r) {
    t.last = runOnce();
    complete = complete && t.last.complete;
    costs.push_back(1000.0 * t.last.wallSeconds / std::max(t.last.simSeconds, timestep));
  }
  t.last.complete = complete;
  t.costMs = median(costs);
  t.spread = (*std::max_element(costs.begin(), costs.end()) - *std::min_element(costs.begin(), costs.end())) / t.costMs;
  return t;
}

// One setting of the grid: a scene, a mode and the settings.
struct GridItem {
  BenchScene* scene;
  SimulationMode mode;
  Settings settings;
};

// Times one setting: the warm-up also makes the scene's reference run, if
// it has none yet.
Timed timeItem(const GridItem& item, int repeats) {
  return timed(repeats, true, item.settings.timestep, [&item] { return item.scene->run(item.settings, item.mode); });
}

BenchPoint pointOf(const GridItem& item, const Timed& t) {
  BenchPoint p{item.scene->name(), item.settings.timestep, item.settings.iterations, item.settings.integrator,
               item.mode};
  p.costMs = t.costMs;
  p.spread = t.spread;
  p.error = t.last.error;
  p.complete = t.last.complete;
  p.reference = item.scene->isReference(item.settings, item.mode);
  return p;
}

std::string describe(const GridItem& item) {
  return item.scene->name() + " " + std::string(toString(item.mode)) + " " + fixed(1.0 / item.settings.timestep, 0) +
         " Hz";
}

// The grid on worker processes (io/ProcessPool.h), a setting at a time
// each, so each timing has a core to itself: first the reference runs,
// a scene each, so that no two workers make the same one; then the
// settings, each row the timing's median, spread, error and completeness.
std::vector<BenchPoint> measureOnWorkers(const std::vector<GridItem>& items, int repeats, int jobs,
                                         const MeasureHooks& hooks) {
  std::vector<BenchScene*> needing;
  for (const GridItem& item : items) {
    if (item.scene->needsReference() && std::find(needing.begin(), needing.end(), item.scene) == needing.end()) {
      needing.push_back(item.scene);
    }
  }
  const auto reference = [&needing](std::size_t k) {
    PoolRow row{k};
    for (const Vec3& c : needing[k]->referenceCentres()) row.push_back({c.x, c.y, c.z});
    return row;
  };
  runProcessPool(0, needing.size(), jobs, reference, [&needing](const PoolRow& row) {
    std::vector<Vec3> centres;
    for (std::size_t k = 1; k < row.size(); ++k) centres.push_back({row[k][0], row[k][1], row[k][2]});
    needing[row[0].get<std::size_t>()]->setReference(std::move(centres));
  }, hooks.stop);
  std::vector<BenchPoint> points;
  if (hooks.stop()) return points;
  const auto setting = [&items, repeats](std::size_t i) {
    const Timed t = timeItem(items[i], repeats);
    return PoolRow{i, t.costMs, t.spread, t.last.error, t.last.complete};
  };
  runProcessPool(0, items.size(), jobs, setting, [&](const PoolRow& row) {
    const GridItem& item = items[row[0].get<std::size_t>()];
    Timed t;
    t.costMs = row[1];
    t.spread = row[2];
    t.last.error = row[3];
    t.last.complete = row[4];
    points.push_back(pointOf(item, t));
    hooks.advance(describe(item));
  }, hooks.stop);
  return points;
}

}  // namespace

std::vector<BenchPoint> measureSweep(std::vector<BenchScene>& scenes, const SweepGrid& grid,
                                     const std::vector<SimulationMode>& modes, int repeats, const MeasureHooks& hooks,
                                     std::map<std::string, std::vector<std::string>>& skipped, int jobs) {
  std::vector<GridItem> items;
  for (BenchScene& scene : scenes) {
    for (SimulationMode mode : modes) {
      if (const auto why = refusal(scene.scenario(), mode)) {
        skipped[scene.name()].push_back("not in mode " + std::string(toString(mode)) + ": " + *why);
        continue;
      }
      for (const Settings& settings : sweep(grid, scene.scenario(), mode)) items.push_back({&scene, mode, settings});
    }
  }
  hooks.start(static_cast<long>(items.size()));
  if (jobs > 1 && items.size() > 1) return measureOnWorkers(items, repeats, jobs, hooks);
  std::vector<BenchPoint> points;
  for (const GridItem& item : items) {
    if (hooks.stop()) return points;
    points.push_back(pointOf(item, timeItem(item, repeats)));
    hooks.advance(describe(item));
  }
  return points;
}

std::vector<BaselinePoint> measureBaseline(std::vector<BenchScene>& scenes, const std::vector<double>& rates,
                                           int repeats, const MeasureHooks& hooks) {
  hooks.start(static_cast<long>(scenes.size() * rates.size()));
  std::vector<BaselinePoint> points;
  for (BenchScene& scene : scenes) {
    // A scene full physics refuses (an overlap, a step that cannot be
    // reached) has no cost to compare.
    const bool refused = refusal(scene.scenario(), SimulationMode::Bullet).has_value();
    for (const double rate : rates) {
      if (hooks.stop()) return points;
      if (refused) {
        hooks.advance(scene.name());
        continue;
      }
      Settings settings = scene.scenario().settings;
      settings.timestep = 1.0 / rate;
      const Timed t = timed(repeats, true, settings.timestep, [&] { return scene.measure(settings); });
      const double simulated = std::max(t.last.simSeconds, settings.timestep);
      const PlainRun plain = runPlainBullet(scene.scenario(), settings.timestep, simulated, repeats);
      points.push_back({scene.name(), rate, t.costMs, plain.costMsPerSecond, simulated});
      hooks.advance(scene.name());
    }
  }
  return points;
}

std::vector<SwitchPoint> measureSwitches(std::vector<BenchScene>& scenes, int repeats, const MeasureHooks& hooks) {
  std::vector<SwitchPoint> points;
  long total = 0;
  for (const BenchScene& scene : scenes) total += static_cast<long>(modelSwitches(scene.scenario().settings).size());
  hooks.start(total);
  for (BenchScene& scene : scenes) {
    std::uint64_t defaults = 0;
    for (const ModelSwitch& m : modelSwitches(scene.scenario().settings)) {
      if (hooks.stop()) return points;
      const Timed t = timed(repeats, true, m.settings.timestep, [&] { return scene.run(m.settings); });
      if (m.name == "defaults") defaults = t.last.hash;
      points.push_back({scene.name(), m.name, t.costMs, t.spread, t.last.error, t.last.hash == defaults, t.last.complete});
      hooks.advance(scene.name() + " " + m.name);
    }
  }
  return points;
}

// The simple broadphase compares every pair: past this many cubes a run
// takes minutes and says nothing new.
constexpr int kSimpleBroadphaseLimit = 1000;

std::vector<ScalePoint> measureScale(const std::vector<int>& sizes, int repeats, const MeasureHooks& hooks) {
  std::vector<ScalePoint> points;
  long total = 0;
  for (int n : sizes) total += static_cast<long>(modelSwitches(CubeField::make(n).settings).size());
  hooks.start(total);
  for (int n : sizes) {
    BenchScene field(CubeField::make(n));
    BenchScene::Run defaults;
    for (const ModelSwitch& m : modelSwitches(field.scenario().settings)) {
      if (hooks.stop()) return points;
      hooks.advance(field.name() + " " + m.name);
      if (m.settings.bullet.broadphase == Broadphase::Simple && n > kSimpleBroadphaseLimit) continue;
      // Large fields run long enough that a warm-up adds nothing but time.
      const Timed t = timed(repeats, n < 1000, m.settings.timestep, [&] { return field.measure(m.settings); });
      if (m.name == "defaults") defaults = t.last;
      ScalePoint p{n, m.name, t.costMs * m.settings.timestep, t.spread, 0.0, t.last.hash == defaults.hash,
                   t.last.complete};
      for (std::size_t i = 0; i < t.last.centres.size() && i < defaults.centres.size(); ++i) {
        p.difference = std::max(p.difference, (t.last.centres[i] - defaults.centres[i]).length());
      }
      points.push_back(p);
    }
  }
  return points;
}

std::map<std::string, double> exponents(const std::vector<ScalePoint>& points) {
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> series;
  for (const ScalePoint& p : points) {
    series[p.name].first.push_back(p.cubes);
    series[p.name].second.push_back(p.msPerStep);
  }
  std::map<std::string, double> out;
  for (const auto& [name, xy] : series) {
    if (xy.first.size() >= 2) out[name] = growthExponent(xy.first, xy.second);
  }
  return out;
}

DriftMatch lowestRateHolding(const Scenario& scenario, const StabilityReport& own, double drift) {
  const auto holds = [drift](const StabilityReport& r) { return r.complete && r.worstDrift <= drift; };
  DriftMatch match;
  // Without weight nothing presses on a support, and a centre that stays
  // put says nothing of the step (free rotation keeps its centre at any).
  if (scenario.settings.gravity <= 0 || !holds(own)) return match;
  const double ownRate = 1.0 / scenario.settings.timestep;
  match = {ownRate, own};
  for (const double rate : kLowerRates) {
    if (rate >= ownRate * (1.0 - 1e-9)) continue;
    Settings settings = scenario.settings;
    settings.timestep = 1.0 / rate;
    StabilityReport r = probeStability(scenario, settings);
    if (!holds(r)) break;
    match = {rate, std::move(r)};
  }
  return match;
}

std::vector<HardPoint> measureHard(const std::string& dir, const MeasureHooks& hooks) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<HardPoint> points;
  hooks.start(static_cast<long>(files.size()));
  for (const std::string& file : files) {
    if (hooks.stop()) break;
    const Scenario s = ScenarioLoader::loadFile(file);
    Settings sweeps = s.settings;
    sweeps.solver = ContactSolver::SequentialImpulse;
    sweeps.iterations = kHardSweeps;
    StabilityReport own = probeStability(s, s.settings);
    DriftMatch match = lowestRateHolding(s, own, kPeerDrift);
    points.push_back({s.name, s.settings, std::move(own), probeStability(s, sweeps),
                      runPlainBullet(s, s.settings.timestep, s.settings.duration, 1), std::move(match)});
    hooks.advance(s.name);
  }
  return points;
}

}  // namespace tabletop
