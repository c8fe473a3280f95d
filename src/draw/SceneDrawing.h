#pragma once

#include <optional>
#include <vector>

#include "core/Arrow.h"
#include "core/EntityState.h"
#include "draw/Camera.h"
#include "draw/DrawList.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// What a frame shows besides the entities.
struct DrawOptions {
  bool arrow = true;     ///< the report's Push Direction (On/Off)
  bool contacts = false; ///< draw contact points
  double floorReach = 0.0; ///< the floor reaches at least this far from the table's centre, metres
};

/// The draw list of `scenario` with its entities where `states` (one per
/// entity, in scenario order, from any mode's snapshot) puts them; the
/// arrow on its face of its entity when given and shown; and `contacts`.
DrawList makeDrawList(const Scenario& scenario, const std::vector<EntityState>& states,
                      const std::optional<Arrow>& arrow, const std::vector<Vec3>& contacts,
                      const DrawOptions& options = {});

/// What a camera fitted to the scene keeps in view: the table (its top and
/// legs) and each entity where `states` puts it, by its bounding radius.
std::vector<Camera::Bound> sceneBounds(const Scenario& scenario, const std::vector<EntityState>& states);

/// The arrow as drawn for an entity of `spec` in `state`: its head touches
/// the pushed face (report 3.3.6), its length is 1.2 times the entity's
/// size, at the height of the entity's centre.
DrawArrow arrowFor(const Arrow& arrow, const EntitySpec& spec, const EntityState& state);

}  // namespace tabletop
