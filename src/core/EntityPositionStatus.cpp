#include "core/EntityPositionStatus.h"

#include "core/EnumNames.h"

namespace tabletop {

std::string_view toString(EntityPositionStatus s) {
  switch (s) {
    case EntityPositionStatus::OnTable: return "OnTable";
    case EntityPositionStatus::DropFromLeftEdge: return "DropFromLeftEdge";
    case EntityPositionStatus::DropFromFrontEdge: return "DropFromFrontEdge";
    case EntityPositionStatus::DropFromRightEdge: return "DropFromRightEdge";
    case EntityPositionStatus::DropFromBackEdge: return "DropFromBackEdge";
    case EntityPositionStatus::FinishDropSimulation: return "FinishDropSimulation";
  }
  return "OnTable";
}

std::optional<EntityPositionStatus> statusFromString(std::string_view name) {
  constexpr EntityPositionStatus all[] = {
      EntityPositionStatus::OnTable,           EntityPositionStatus::DropFromLeftEdge,
      EntityPositionStatus::DropFromFrontEdge, EntityPositionStatus::DropFromRightEdge,
      EntityPositionStatus::DropFromBackEdge,  EntityPositionStatus::FinishDropSimulation};
  return enumFromName(name, all);
}

bool isDropping(EntityPositionStatus s) { return !edgeName(s).empty(); }

std::string_view edgeName(EntityPositionStatus s) {
  switch (s) {
    case EntityPositionStatus::DropFromLeftEdge: return "Left";
    case EntityPositionStatus::DropFromFrontEdge: return "Front";
    case EntityPositionStatus::DropFromRightEdge: return "Right";
    case EntityPositionStatus::DropFromBackEdge: return "Back";
    default: return "";
  }
}

}  // namespace tabletop
