// Micro-benchmarks of the step path, with Google Benchmark. They are built
// with the tests and run once by CTest to show they work; their times are
// for a developer comparing two builds on one machine
//   build/tests/tabletop_microbench --benchmark_repetitions=5
// and are never asserted on (speed goals are measured by tabletop bench).

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/StateHash.h"
#include "scenario/ScenarioLoader.h"
#include "scenes/CubeField.h"
#include "sim/DivergenceGuard.h"
#include "physics/World.h"
#include "sim/SceneBuilder.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

Scenario shipped(const std::string& name) {
  return ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/" + name + ".json");
}

// A whole report example, built and played to its end in one mode; the
// counter is the steps taken per second of wall time.
void runExample(benchmark::State& state, const char* name, SimulationMode mode) {
  const Scenario s = shipped(name);
  long steps = 0;
  for (auto _ : state) {
    const RunResult r = test::runScene(s, mode);
    steps += r.steps;
    benchmark::DoNotOptimize(r.stateHash);
  }
  state.counters["steps"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(runExample, example2_bullet, "example2_two_cubes", SimulationMode::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(runExample, example2_compat, "example2_two_cubes", SimulationMode::Compat)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(runExample, example2_rules, "example2_two_cubes", SimulationMode::Rules)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(runExample, example3_bullet, "example3_stacked_cubes", SimulationMode::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(runExample, example4_bullet, "example4_two_spheres", SimulationMode::Bullet)->Unit(benchmark::kMillisecond);

// One step of the cube field of range(0) cubes, from its pushes on; the
// field is rebuilt (untimed) once its fixed duration has passed, so every
// timed step is one of moving, colliding cubes.
void stepCubeField(benchmark::State& state) {
  const Scenario s = CubeField::make(static_cast<int>(state.range(0)));
  const long perRun = std::lround(CubeField::kDuration / s.settings.timestep);
  std::unique_ptr<World> world;
  long taken = perRun;
  for (auto _ : state) {
    if (taken == perRun) {
      state.PauseTiming();
      world = buildWorld(s, s.settings);
      for (const Action& a : s.script) world->push(a.arrow, a.magnitude);
      taken = 0;
      state.ResumeTiming();
    }
    world->step();
    ++taken;
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));  // cube-steps
}
BENCHMARK(stepCubeField)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

// The checks made after every step, for n bodies: the divergence guard and
// the state hash.
void guardCheck(benchmark::State& state) {
  const Scenario s = CubeField::make(static_cast<int>(state.range(0)));
  auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  const std::vector<BodyMotion> motions = sim->motions();
  const DivergenceGuard guard(s, s.settings, motions);
  for (auto _ : state) guard.check(motions, 0.0);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(guardCheck)->Arg(10)->Arg(1000);

void hashState(benchmark::State& state) {
  const Scenario s = CubeField::make(static_cast<int>(state.range(0)));
  auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  const std::vector<EntityState> entities = sim->snapshot();
  for (auto _ : state) benchmark::DoNotOptimize(stateHash(entities));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(hashState)->Arg(10)->Arg(1000);

}  // namespace
}  // namespace tabletop

BENCHMARK_MAIN();
