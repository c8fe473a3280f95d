#pragma once

#include <optional>
#include <string_view>

#include "core/DirectionDef.h"

namespace tabletop {

/// The report's EntityPositionStatus (report 2): on the table, dropping from
/// one of its edges, or done dropping and at rest below the table top.
enum class EntityPositionStatus {
  OnTable,
  DropFromLeftEdge,
  DropFromFrontEdge,
  DropFromRightEdge,
  DropFromBackEdge,
  FinishDropSimulation,
};

/// The report's name of a status ("OnTable", ...).
std::string_view toString(EntityPositionStatus s);

/// Parses a report status name; nullopt if it is not one.
std::optional<EntityPositionStatus> statusFromString(std::string_view name);

/// True for the four DropFrom...Edge values.
bool isDropping(EntityPositionStatus s);

/// The edge's name in a DropFrom...Edge status ("Left", ...); empty otherwise.
std::string_view edgeName(EntityPositionStatus s);

/// The edge a DropFrom...Edge status names, as the side of the table it is
/// on (the report names edges as it names faces); nothing otherwise.
std::optional<DirectionDef> dropEdge(EntityPositionStatus s);

}  // namespace tabletop
