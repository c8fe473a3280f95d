#pragma once

#include <memory>

#include "physics/World.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// Builds the Bullet scene (mode "bullet") a scenario describes: the table,
/// the ground and each entity, resting on what its "on" names. Throws a
/// ScenarioError naming the entities when two bodies start interpenetrating.
std::unique_ptr<World> buildWorld(const Scenario& scenario, const Settings& settings);

/// The Shape a scenario entity describes, not yet a body.
std::unique_ptr<Shape> makeShape(const EntitySpec& entity);

}  // namespace tabletop
