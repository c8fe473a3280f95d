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

/// True when a body with its centre at `centre` and its lowest point at
/// `bottom` hangs over the table top: its centre within the edges (report
/// 3.4) and its bottom no lower than the top, at `topHeight`, within
/// `slack` metres. What falls from there lands on the table.
bool overTableTop(const Vec3& centre, double bottom, const TableEdges& table, double topHeight, double slack);

/// The share (0 to 1) of a step at which a centre crossed the edge that
/// `drop` names, going from `p0` with velocity `v0` to `p1` with `v1` in
/// `dt` seconds: where the quadratic through both places and the start's
/// velocity (exact for a constant acceleration, such as sliding friction)
/// meets the edge's line. 1 when it does not cross within the step.
double edgeCrossing(const Vec3& p0, const Vec3& v0, const Vec3& p1, double dt, EntityPositionStatus drop,
                    const TableEdges& table);

}  // namespace tabletop
