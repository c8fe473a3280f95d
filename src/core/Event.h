#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/DirectionDef.h"
#include "core/Support.h"

namespace tabletop {

/// What can happen to entities during a run.
enum class EventType {
  Push,          ///< an impulse was applied (entity)
  Rotate,        ///< an entity was turned about its vertical axis (entity)
  ContactBegin,  ///< two entities started touching (entity, other)
  LeavesTable,   ///< an entity's centre passed a table edge (entity, edge)
  Lands,         ///< an entity in the air came down on a new support (entity, on)
  AtRest,        ///< an entity stopped moving (entity)
};

/// The output name of an event type ("push", "contact_begin", ...).
const char* toString(EventType t);

/// One timed event. Fields that do not apply to the type stay empty / NaN.
struct Event {
  double t = 0.0;  ///< simulated time, seconds
  EventType type = EventType::Push;
  std::string entity;
  std::string other;      ///< ContactBegin: the second entity
  std::optional<DirectionDef> edge;  ///< LeavesTable: the table edge passed
  Support on;                        ///< Lands: what it landed on
  std::optional<DirectionDef> face;  ///< Push: the face pushed, or nothing for an angle
  double angle = 0.0;     ///< Push: world angle (report 3.8); Rotate: degrees turned
  double impulse = 0.0;   ///< Push: N*s
  double step = 0.0;      ///< Push: metres, when the push was given as a step
};

/// The entities an event names, in order.
std::vector<std::string> eventEntities(const Event& e);

}  // namespace tabletop
