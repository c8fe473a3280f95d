#pragma once

#include <memory>

#include "core/Simulation.h"
#include "core/SimulationMode.h"
#include "rules/RuleBody.h"
#include "scenario/Scenario.h"

namespace tabletop {

// Bullet's scene, declared only: a caller of buildWorld() or makeShape()
// includes physics/World.h itself, so building a scene in any mode does
// not pull Bullet's headers in.
class Shape;
class World;

/// Builds the Bullet scene (mode "bullet") a scenario describes: the table,
/// the ground and each entity, resting on what its "on" names. Throws a
/// ScenarioError naming the entities when two bodies start interpenetrating.
std::unique_ptr<World> buildWorld(const Scenario& scenario, const Settings& settings);

/// The scenario's entities as the report's rules see them, each resting
/// exactly on what its "on" names.
std::vector<rules::RuleBody> buildRuleBodies(const Scenario& scenario);

/// The scene in `mode`: "bullet" (buildWorld), "compat" (a CompatWorld)
/// or "rules" (a RuleEngine with the report's predicates). Every mode
/// refuses the same bad scenes with the same ScenarioError.
std::unique_ptr<Simulation> buildSimulation(const Scenario& scenario, const Settings& settings,
                                            SimulationMode mode);

/// The Shape a scenario entity describes, not yet a body.
std::unique_ptr<Shape> makeShape(const EntitySpec& entity);

}  // namespace tabletop
