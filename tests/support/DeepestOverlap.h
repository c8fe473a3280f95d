#pragma once

#include <btBulletCollisionCommon.h>

#include "core/Simulation.h"
#include "measure/StabilityProbe.h"
#include "physics/collision/ClosestPoints.h"
#include "physics/contact/ContactKinematics.h"
#include "physics/World.h"
#include "scenario/Scenario.h"

namespace tabletop::test {

/// How far two entities of a run went into each other, at their deepest:
/// GJK's depth between their shapes after every step (not the contacts',
/// which could miss a part that sank), m, and when.
struct Overlap {
  StabilityReport report;  ///< the run's own (complete, energy)
  double deepest = 0.0;
  double at = 0.0;  ///< s
};

/// Runs `scenario` (full physics, its own settings) and measures how deep
/// entity `a` went into entity `b` (their indices in the scenario).
inline Overlap deepestOverlap(const Scenario& scenario, std::size_t a, std::size_t b) {
  Overlap o;
  o.report = probeStability(scenario, scenario.settings, [&](const Simulation& sim) {
    const auto& world = dynamic_cast<const World&>(sim);
    const Shape& first = *world.entities().at(a);
    const Shape& second = *world.entities().at(b);
    const btPointCollector closest =
        closestPoints(static_cast<const btConvexShape&>(first.collisionShape()), first.body()->getWorldTransform(),
                      static_cast<const btConvexShape&>(second.collisionShape()), second.body()->getWorldTransform());
    if (closest.m_hasResult && -closest.m_distance > o.deepest) o.deepest = -closest.m_distance, o.at = sim.time();
  });
  return o;
}

}  // namespace tabletop::test
