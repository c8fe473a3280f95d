#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "physics/contact/BodySet.h"
#include "physics/step/PartGuards.h"

namespace tabletop {

/// Bodies leaving the face of a box that carries them (the table top, a
/// cube under a rider): the report's "drops off once its centre passes
/// the edge", at its own time inside a step.
///
/// A part's contacts are found at its start and the solver holds them for
/// the whole part, so a body whose centre passed the edge inside a part
/// stayed carried to the part's end: a cube began to tip, a ball to fall,
/// up to a part's travel late (a ball landed long, by where in a step it
/// met the edge). The part is now
/// cut where the centre reaches the edge (DynamicsWorld), and a ball's row
/// at an edge counts the curvature of its path about it.

/// The box of a body that each contact point lies on, on either side (the
/// body itself, or a compound's box child such as the table top; none if
/// it is not a box there), found once a part: earliestFaceExit,
/// holdEdgeCurvature and holdEdgeLevers ask for the same ones, and
/// between them no body moves and no point is found again (a point moved
/// since it was looked up is looked up afresh). start() before a part's
/// first scan, after anything that moves a body.
class PointBoxes {
 public:
  struct Box {
    btTransform place;  // the box's frame in the world
    btVector3 half;     // its outer half extents
  };
  void start(btDispatcher& dispatcher);
  /// The box of point `p` of manifold `m` (its index in the dispatcher),
  /// on the body of `side` (0: the manifold's body 0, at the point's place
  /// on it; 1: body 1).
  const std::optional<Box>& at(const btPersistentManifold& manifold, int m, int p, int side);

 private:
  struct Entry {
    bool known[2] = {false, false};
    btVector3 place[2];
    std::optional<Box> box[2];
  };
  std::vector<std::size_t> first_;  // each manifold's first entry
  std::vector<Entry> entries_;
};

/// The earliest time within `horizon`, s, at which the centre of a body
/// touching the upward face of a box reaches that face's edge, moving at
/// its velocity relative to the box; `horizon` if none, or if the centre
/// is already within a thousandth of the part's travel of it.
/// With `eventful`, the bodies of every exit within `horizon` are added.
double earliestFaceExit(btDispatcher& dispatcher, double horizon, PointBoxes& boxes, BodySet* eventful = nullptr);

/// Readies the rows of balls at a box's edge or corner (the centre past
/// the face), and of two balls, for a part `length` s long of a step
/// `stepLength` s long. Bullet's row is the distance's first-order change;
/// about an edge, or another ball, the distance also grows with the square
/// of the ball's speed across the line to it, v^2 t^2 / (2 R), R the
/// centre's distance from the edge (or the other centre). Without it a
/// ball leaving the edge faster than sqrt(g R) was held up for a part, and
/// two balls meeting obliquely were slowed before they touched and pressed
/// together after an inelastic impact. Each such
/// point's gap is raised by that growth over the part (and, with
/// `meanVelocity`, for positions that follow the mean of the part's
/// velocities), but for a point striking now (strikesNow), which the
/// impact stops; `saved` gets the points and their gaps, to be put back
/// after the solve.
void holdEdgeCurvature(btDispatcher& dispatcher, double length, double stepLength, bool meanVelocity,
                       std::vector<std::pair<btManifoldPoint*, btScalar>>& saved, PointBoxes& boxes);

/// Readies for a part `length` s long the points where a box's face is cut
/// by the edge of the box face under it (a cube overhanging the table top
/// or the cube under it). Such a point stays on that edge while the body
/// moves across it, so its lever about the body's centre changes within
/// the part; the solver takes it from the part's start, where a cube whose
/// centre has just reached the edge is held level for the whole part, and
/// its tip lagged by half a part. Each such point, on
/// the carried body's side, is moved back by half the part's motion across
/// the edge: to where it is, relative to the body, at mid-part. `saved`
/// gets the points and their places, to be put back after the solve.
void holdEdgeLevers(btDispatcher& dispatcher, double length, std::vector<HeldPlace>& saved, PointBoxes& boxes);

}  // namespace tabletop
