#include "core/TableEdges.h"

namespace tabletop {

EntityPositionStatus dropStatus(const Vec3& c, const TableEdges& t) {
  if (c.x > t.xRight) return EntityPositionStatus::DropFromRightEdge;
  if (c.x < t.xLeft) return EntityPositionStatus::DropFromLeftEdge;
  if (c.z > t.zFront) return EntityPositionStatus::DropFromFrontEdge;
  if (c.z < t.zBack) return EntityPositionStatus::DropFromBackEdge;
  return EntityPositionStatus::OnTable;
}

}  // namespace tabletop
