#include "measure/RandomRunCheck.h"

#include <algorithm>
#include <cmath>

#include "physics/World.h"
#include "scenes/RandomScene.h"

namespace tabletop {

RandomRunCheck checkRandomRun(std::uint64_t seed, double timestep, const StepObserver& afterStep) {
  Scenario s = RandomScene::make(seed);
  if (timestep > 0) s.settings.timestep = timestep;
  RandomRunCheck c;
  c.seed = seed;
  c.bodies = static_cast<int>(s.entities.size());
  c.pushes = static_cast<int>(s.script.size());
  double below = 0.0;  // the lowest any body's highest point came, m
  c.report = probeStability(s, s.settings, [&](const Simulation& sim) {
    for (const auto& e : dynamic_cast<const World&>(sim).entities()) {
      below = std::min(below, e->reach(btVector3(0, 1, 0)));
    }
    if (afterStep) afterStep(sim);
  });
  c.underFloor = below < 0.0 ? -below : 0.0;
  double lightest = s.entities.at(0).mass;
  for (const EntitySpec& e : s.entities) lightest = std::min(lightest, e.mass);
  const StabilityReport& r = c.report;
  c.reach = std::hypot(0.5 * s.table.width, 0.5 * s.table.depth) +
            std::sqrt(2.0 * r.energyScale / lightest) * r.simulated;
  if (!r.complete) {
    c.reason = r.failure.empty() ? "did not finish" : r.failure;
  } else if (below < 0.0) {
    c.reason = "a body went wholly under the floor, " + std::to_string(-below) + " m";
  } else if (r.farthest > c.reach) {
    c.reason = "a body got " + std::to_string(r.farthest) + " m out";
  } else if (r.energyExcess > RandomRunCheck::kExcessShare * r.energyScale) {
    c.reason = "energy excess " + std::to_string(r.energyExcess) + " J";
  } else if (r.energyGain > RandomRunCheck::kGainShare * r.energyScale) {
    c.reason = "energy gain " + std::to_string(r.energyGain) + " J";
  }
  return c;
}

}  // namespace tabletop
