#pragma once

#include <optional>
#include <string_view>

#include "core/DirectionDef.h"
#include "core/Support.h"

namespace tabletop {

/// The report's EntityPositionStatus (report 2): on the table, dropping from
/// one of its edges, or done dropping and at rest below the table top; and
/// two of our own for an entity that was never on the table: OffTable
/// while it moves or falls, OnGround once down (on the ground, or on
/// something that is).
enum class EntityPositionStatus {
  OnTable,
  DropFromLeftEdge,
  DropFromFrontEdge,
  DropFromRightEdge,
  DropFromBackEdge,
  FinishDropSimulation,
  OffTable,
  OnGround,
};

/// The report's name of a status ("OnTable", ...).
std::string_view toString(EntityPositionStatus s);

/// Parses a report status name; nullopt if it is not one.
std::optional<EntityPositionStatus> statusFromString(std::string_view name);

/// True for the four DropFrom...Edge values.
bool isDropping(EntityPositionStatus s);

/// The edge's name in a DropFrom...Edge status ("Left", ...); empty otherwise.
std::string_view edgeName(EntityPositionStatus s);

/// True for OffTable and OnGround: the entity was never on the table.
bool neverOnTable(EntityPositionStatus s);

// One rule for the status, in every mode (bullet, compat, rules):
// - An entity starts OnTable, or OffTable if it was never on it
//   (startStatus).
// - OnTable turns DropFrom...Edge once the centre passes an edge
//   (report 3.4, dropStatus in TableEdges.h).
// - Whenever a mode judges whether an entity is down (comeDown): a drop
//   ends, FinishDropSimulation for good; an entity never on the table is
//   OnGround while down and OffTable while not, or OnTable once it comes
//   down on the table top.
// What "down" means is the mode's: landed on what stays up (rules), at rest
// (physics; below the table top for a drop, as a body tipping at an edge
// is slow before it falls).

/// The status an entity starts with: OnTable when what holds it up,
/// followed down, ends on the table (`heldBy`, Kind::Table), or when
/// nothing holds it up (Kind::None) and it hangs over the table top
/// (`overTableTop`); else OffTable, never on the table.
EntityPositionStatus startStatus(Support::Kind heldBy, bool overTableTop);

/// The status once a mode has judged whether the entity is `down`, and
/// whether what holds it up ends on the table (`onTableTop`); see above.
EntityPositionStatus comeDown(EntityPositionStatus s, bool down, bool onTableTop);

/// The edge a DropFrom...Edge status names, as the side of the table it is
/// on (the report names edges as it names faces); nothing otherwise.
std::optional<DirectionDef> dropEdge(EntityPositionStatus s);

}  // namespace tabletop
