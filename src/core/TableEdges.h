#pragma once

#include "core/EntityPositionStatus.h"
#include "core/Vec3.h"

namespace tabletop {

/// The table top's edges (report 3.4): X_L < X_R, Z_B < Z_F. Every mode
/// drops an entity by the same test, so it lives with the vocabulary.
struct TableEdges {
  double xLeft;
  double xRight;
  double zBack;
  double zFront;
};

/// Report 3.4: OnTable while the centre is within the edges (inclusive),
/// else DropFrom...Edge for the first edge passed, tested in the order
/// X > X_R, X < X_L, Z > Z_F, Z < Z_B.
EntityPositionStatus dropStatus(const Vec3& centre, const TableEdges& table);

}  // namespace tabletop
