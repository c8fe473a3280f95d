#include "sim/Benchmark.h"

#include <algorithm>
#include <cmath>

#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {

BenchScene::BenchScene(Scenario scenario)
    : scenario_(std::move(scenario)), analytic_(AnalyticCase::forScenario(scenario_)) {}

BenchScene::Run BenchScene::run(const Settings& settings, SimulationMode mode) {
  // The wall time is the script's, stepping only: building the scene is
  // not part of the cost per simulated second.
  Run out;
  if (analytic_) {
    const AnalyticResult r = analytic_->run(scenario_, settings, mode);
    out.wallSeconds = r.run.wallSeconds;
    out.error = r.positionError;
    out.simSeconds = r.run.simTime;
    out.complete = r.run.complete;
    return out;
  }
  auto simulation = buildSimulation(scenario_, settings, mode);
  const RunResult r = runScript(scenario_, settings, *simulation);
  out.wallSeconds = r.wallSeconds;
  out.simSeconds = r.simTime;
  out.complete = r.complete;
  if (!reference_) {
    Settings fine = settings;
    fine.timestep = kReferenceTimestep;
    fine.iterations = kReferenceIterations;
    fine.integrator = Integrator::Trapezoid;
    // Full physics is the reference of every mode: what compat and rules
    // give up by following the report's rules shows as their error.
    auto reference = buildSimulation(scenario_, fine, SimulationMode::Bullet);
    const RunResult ref = runScript(scenario_, fine, *reference);
    reference_.emplace();
    for (const EntityState& e : ref.entities) reference_->push_back(e.position);
  }
  for (std::size_t i = 0; i < r.entities.size() && i < reference_->size(); ++i) {
    out.error = std::max(out.error, (r.entities[i].position - (*reference_)[i]).length());
  }
  return out;
}

void markParetoFronts(std::vector<BenchPoint>& points) {
  for (BenchPoint& p : points) {
    p.front = p.complete;
    for (const BenchPoint& q : points) {
      if (&q == &p || q.scene != p.scene || !q.complete) continue;
      const bool noWorse = q.costMs <= p.costMs && q.error <= p.error;
      const bool better = q.costMs < p.costMs || q.error < p.error;
      if (noWorse && better) {
        p.front = false;
        break;
      }
    }
  }
}

}  // namespace tabletop
