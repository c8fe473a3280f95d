#include "measure/Benchmark.h"

#include <algorithm>
#include <cmath>

#include "core/StateHash.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {

BenchScene::BenchScene(Scenario scenario)
    : scenario_(std::move(scenario)), analytic_(AnalyticCase::forScenario(scenario_)) {}

namespace {

void collect(const RunResult& r, BenchScene::Run& out) {
  out.wallSeconds = r.wallSeconds;
  out.simSeconds = r.simTime;
  out.complete = r.complete;
  out.hash = stateHash(r.entities);
  out.centres.clear();
  for (const EntityState& e : r.entities) out.centres.push_back(e.position);
}

}  // namespace

bool BenchScene::isReference(const Settings& settings, SimulationMode mode) const {
  return !analytic() && mode == SimulationMode::Bullet && settings.timestep == kReferenceTimestep &&
         settings.iterations == kReferenceIterations && settings.integrator == Integrator::Trapezoid;
}

BenchScene::Run BenchScene::run(const Settings& settings, SimulationMode mode) {
  // The wall time is the script's, stepping only: building the scene is
  // not part of the cost per simulated second.
  Run out;
  if (analytic_) {
    const AnalyticResult r = analytic_->run(scenario_, settings, mode);
    collect(r.run, out);
    out.error = r.positionError;
    return out;
  }
  out = measure(settings, mode);
  if (!reference_) reference_ = referenceCentres();
  for (std::size_t i = 0; i < out.centres.size() && i < reference_->size(); ++i) {
    out.error = std::max(out.error, (out.centres[i] - (*reference_)[i]).length());
  }
  return out;
}

std::vector<Vec3> BenchScene::referenceCentres() const {
  Settings fine = scenario_.settings;
  fine.timestep = kReferenceTimestep;
  fine.iterations = kReferenceIterations;
  fine.integrator = Integrator::Trapezoid;
  // Full physics is the reference of every mode: what compat and rules
  // give up by following the report's rules shows as their error.
  auto reference = buildSimulation(scenario_, fine, SimulationMode::Bullet);
  const RunResult ref = runScript(scenario_, fine, *reference);
  std::vector<Vec3> centres;
  for (const EntityState& e : ref.entities) centres.push_back(e.position);
  return centres;
}

BenchScene::Run BenchScene::measure(const Settings& settings, SimulationMode mode) {
  Run out;
  auto simulation = buildSimulation(scenario_, settings, mode);
  collect(runScript(scenario_, settings, *simulation), out);
  return out;
}

double growthExponent(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += std::log(x[i]);
    my += std::log(y[i]);
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxx > 0.0 ? sxy / sxx : std::nan("");
}

void markParetoFronts(std::vector<BenchPoint>& points) {
  for (BenchPoint& p : points) {
    p.front = p.complete && !p.reference;
    for (const BenchPoint& q : points) {
      if (&q == &p || q.scene != p.scene || !q.complete || q.reference) continue;
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
