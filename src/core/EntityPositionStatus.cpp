#include "core/EntityPositionStatus.h"

#include "core/EnumNames.h"

namespace tabletop {
namespace {

// The names in scenario files, on the command line and in the output.
constexpr EnumName<EntityPositionStatus> kNames[] = {
    {EntityPositionStatus::OnTable, "OnTable"},
    {EntityPositionStatus::DropFromLeftEdge, "DropFromLeftEdge"},
    {EntityPositionStatus::DropFromFrontEdge, "DropFromFrontEdge"},
    {EntityPositionStatus::DropFromRightEdge, "DropFromRightEdge"},
    {EntityPositionStatus::DropFromBackEdge, "DropFromBackEdge"},
    {EntityPositionStatus::FinishDropSimulation, "FinishDropSimulation"},
    {EntityPositionStatus::OffTable, "OffTable"},
    {EntityPositionStatus::OnGround, "OnGround"}};

}  // namespace

std::string_view toString(EntityPositionStatus s) { return nameOf(s, kNames); }

std::optional<EntityPositionStatus> statusFromString(std::string_view name) { return valueNamed(name, kNames); }

bool isDropping(EntityPositionStatus s) { return !edgeName(s).empty(); }

bool neverOnTable(EntityPositionStatus s) {
  return s == EntityPositionStatus::OffTable || s == EntityPositionStatus::OnGround;
}

EntityPositionStatus startStatus(Support::Kind heldBy, bool overTableTop) {
  const bool onTable = heldBy == Support::Kind::Table || (heldBy == Support::Kind::None && overTableTop);
  return onTable ? EntityPositionStatus::OnTable : EntityPositionStatus::OffTable;
}

EntityPositionStatus comeDown(EntityPositionStatus s, bool down, bool onTableTop) {
  if (isDropping(s)) return down ? EntityPositionStatus::FinishDropSimulation : s;
  if (!neverOnTable(s)) return s;
  if (!down) return EntityPositionStatus::OffTable;
  return onTableTop ? EntityPositionStatus::OnTable : EntityPositionStatus::OnGround;
}

std::optional<DirectionDef> dropEdge(EntityPositionStatus s) {
  switch (s) {
    case EntityPositionStatus::DropFromLeftEdge: return DirectionDef::Left;
    case EntityPositionStatus::DropFromFrontEdge: return DirectionDef::Front;
    case EntityPositionStatus::DropFromRightEdge: return DirectionDef::Right;
    case EntityPositionStatus::DropFromBackEdge: return DirectionDef::Back;
    default: return std::nullopt;
  }
}

std::string_view edgeName(EntityPositionStatus s) {
  const auto edge = dropEdge(s);
  return edge ? toString(*edge) : std::string_view();
}

}  // namespace tabletop
