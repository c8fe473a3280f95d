#pragma once

#include <functional>
#include <algorithm>
#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "physics/contact/BodySet.h"
#include "physics/contact/ContactKey.h"
#include "physics/contact/PointFlags.h"

namespace tabletop {

/// Slips that turn round, or stop, inside a part of a step. Kinetic friction is
/// constant while two bodies slide, so their slip changes linearly until
/// it reaches zero, where static friction may hold it or it may turn round
/// (a rider overtaking the cube under it when the table brakes that cube
/// harder than the rider's friction can follow). A part's solve gives one
/// friction for the whole part, the one of its end: a slip that turned
/// round inside it had the end's friction all through. The rider of
/// scenarios/analytic/stack_rider_slips lost twice mu g times the time
/// before the turn and ended short; the error fell only as fast as the
/// step. Likewise a slip that stopped inside a
/// part was held still all through it. The part is now cut where the slip
/// reaches zero and solved again (PartSolve.cpp).

/// A point whose bodies slide over each other at a part's start.
struct Slip {
  const btPersistentManifold* manifold;
  const btManifoldPoint* point;
  btVector3 velocity;  // A's over B's at the point, m/s
};

/// The points whose slip at the start of a part `length` s long is more
/// than `share` of what kinetic friction (under gravity `g`, m/s^2) takes
/// from it in the part: those whose friction may stop or turn it there.
/// Written to `out` (its storage kept from part to part).
void slippingPoints(btDispatcher& dispatcher, double g, double length, double share, std::vector<Slip>& out);

/// Of `slips`, those on contacts that `counts` and between bodies of which
/// one carries or rides on another moving body: the slips a part may be
/// cut at. A lone body's velocity stays from where its slip stops, which
/// DynamicsWorld's slip share already places exactly; cut there, a
/// standing cylinder was left rocking on its rim by the sweeps of the part
/// after. Found before the solve, so a
/// part with none is not saved to be solved again. Written to `out`;
/// `touching` is scratch (the bodies touching another moving body, found
/// in one pass over the manifolds, so the cost is slips plus manifolds).
void slipsThatMayTurn(btDispatcher& dispatcher, const std::vector<Slip>& slips,
                      const std::function<bool(const Slip&)>& counts, BodySet& touching, std::vector<Slip>& out);

/// After a part's solve, the time from its start, s, at which the earliest
/// slip of `slips` (slipsThatMayTurn's) that ended the part turned round or
/// stopped reached zero; `length` (the part's) if none did, or only within
/// a hundredth of the part from either end. The slip's speed along its
/// first direction went from a to b with the friction the solve found
/// (b < 0: turned, the end's friction all through; b = 0: stopped, a share
/// of it). Had kinetic friction mu N (N the contact's normal impulse) acted
/// against the slip all through, b would be less by k (mu N - F), F the
/// friction the solve used against it and k the slip's change per unit of
/// friction impulse (the inverse masses, and the turning for a lone point).
/// The time is where that line crosses zero: for a cube sliding to rest,
/// a / (mu g).
struct SlipTurn {
  double time;                            // s from the part's start
  const btPersistentManifold* manifold;  // the contact it turned on (none: no turn)
  const btManifoldPoint* point;           // the point of it
  btVector3 along;                        // the slip's direction before, unit
  bool reversed;                          // it turned round (else it stopped)
};
SlipTurn earliestSlipTurn(const std::vector<Slip>& slips, double g, double length, double share);

/// What a part's solve changes, kept to solve the part again: each moving
/// body's place and velocities, each contact point's impulses.
class PartStart {
 public:
  void save(const btAlignedObjectArray<btRigidBody*>& bodies, btDispatcher& dispatcher);
  void restore() const;

 private:
  struct Body {
    btRigidBody* body;
    btTransform place;
    btVector3 linear, angular;
  };
  struct Point {
    btManifoldPoint* point;
    btScalar normal, lateral1, lateral2;
  };
  std::vector<Body> bodies_;
  std::vector<Point> points_;
};

}  // namespace tabletop
