#pragma once

#include "core/Boundary.h"
#include "core/EntityPositionStatus.h"
#include "core/TableEdges.h"
#include "core/Vec3.h"

/// The report's kinematic rules as pure functions (no Bullet, no GL), one
/// per rule, each citing its section of the report. Where the report's
/// printed formula has a typo (REPORT_SPEC section 8) the function follows
/// the intended meaning; the printed form is kept where a test shows the
/// difference.
namespace tabletop::rules {

/// Report 3.8: where a push of `step` metres at `angleDegrees` moves a
/// centre: X' = X + Step cos(Angle), Y' = Y, Z' = Z - Step sin(Angle).
Vec3 stepTarget(const Vec3& centre, double step, double angleDegrees);

/// Report 3.5 (with the erratum on "not alignment"): two cubes are aligned
/// when one's X extent contains the other's, or one's Z extent contains the
/// other's.
bool aligned(const Boundary& a, const Boundary& b);

/// The horizontal axis a cube-cube test runs along (report 3.6.1).
enum class ForceAxis { X, Z };

/// Report 3.6.1 as intended: cubes collide when they overlap strictly along
/// the force (|X1 - X2| < SL1/2 + SL2/2 for a force along X; touching is
/// no collision) and their extents across it overlap, inclusively (either
/// cube's near or far face within the other's range; touching counts).
bool cubesCollide(const Vec3& c1, double side1, const Vec3& c2, double side2, ForceAxis axis);

/// Report 3.6.1 as printed for a force along Z: the across test uses
/// X1 -/+ SideLength1 without the /2, and the along test
/// SideLength1 + SideLength2 where the half sides are meant. Kept only so a
/// test can show where the typo changes the answer.
bool cubesCollideAsPrintedAlongZ(const Vec3& c1, double side1, const Vec3& c2, double side2);

/// Report 3.6.2: spheres collide when the distance of their centres is at
/// most R1 + R2 (touching counts).
bool spheresCollide(const Vec3& c1, double radius1, const Vec3& c2, double radius2);

/// Report 3.7 (with the erratum: the step's own X and Z components, not one
/// itsStep for both): a sphere stays on the table when its target
/// satisfies X_L <= X + step_x <= X_R and Z_B <= Z + step_z <= Z_F.
bool sphereStaysOnTable(const Vec3& centre, double step, double angleDegrees, const TableEdges& table);

}  // namespace tabletop::rules
