#include "physics/step/DynamicsWorld.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/contact/ContactKinematics.h"

// Slips that stop or turn round inside a part (DynamicsWorld, SlipEvents).
namespace tabletop {

// The points of the contact whose slip turned round or stopped at the
// start of this part get their friction rows along and across the line it
// slid on; after a turn, the first row only. They start still, so Bullet
// would lay its rows along the world's axes, and the pivoted solve's rows,
// each bounded by mu N on its own, would brake a slip that starts along
// the line at up to 45 degrees to it and sqrt(2) times too hard (a rider
// slipping on at 37 degrees to the axes after its slip stopped veered and
// ended 0.15 mm short at 60 Hz, 0.9 mm at 30 Hz). The line is taken the way
// round nearest Bullet's own first axis, so that along the axes the rows
// are those Bullet would make.
std::vector<btManifoldPoint*> DynamicsWorld::holdFrictionAlongLine() {
  std::vector<btManifoldPoint*> held;
  if (!lastSlipEnd_) return held;
  const auto& [key, along, reversed] = *lastSlipEnd_;
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    if (contactOf(*manifold) != key) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      const btVector3& n = point.m_normalWorldOnB;
      const btVector3 first = along - n * along.dot(n);
      if (!(first.length2() > 0)) continue;
      btVector3 axis1, axis2;
      btPlaneSpace1(n, axis1, axis2);
      point.m_lateralFrictionDir1 = first.dot(axis1) < 0 ? -first.normalized() : first.normalized();
      point.m_lateralFrictionDir2 = n.cross(point.m_lateralFrictionDir1);
      point.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
      if (reversed) point.m_contactPointFlags |= kFirstFrictionRowOnly;
      held.push_back(&point);
    }
  }
  return held;
}

// A contact slipping at the part's start because a body of it was pushed
// or set moving since the last part (noteKicked), and not resisted by
// rolling resistance (which makes a slip of its own just before the
// solve): its slip stops inside the part if friction can stop it there.
// A slide of 0.08 mm pushed at 30 Hz went 0.33 mm, and a cube spun at
// 5 rad/s with mu = 0.6 did not turn. (Slips a landing or a rocking body
// starts a part with are not these: there the velocity across the normal
// changes with the turn too, and a box toppling onto its side went twice
// as deep.)
bool DynamicsWorld::slidIn(const ContactKey& key) const {
  if (!kicked_.contains(key.first) && !kicked_.contains(key.second)) return false;
  if (!resistedBodies_.contains(key.first) && !resistedBodies_.contains(key.second)) return true;
  const ResistedSlip* slip = resistedSlip(key);
  return slip != nullptr && slip->slippedBefore;
}

const DynamicsWorld::ResistedSlip* DynamicsWorld::resistedSlip(const ContactKey& key) const {
  // The first recorded for the contact: resistedOrder_ is by key, then
  // by the order recorded.
  const auto at = std::lower_bound(resistedOrder_.begin(), resistedOrder_.end(), key,
                                   [&](std::size_t i, const ContactKey& k) { return resistedSlips_[i].contact < k; });
  return at == resistedOrder_.end() || resistedSlips_[*at].contact != key ? nullptr : &resistedSlips_[*at];
}

// Which contacts slid through this part, and which stopped in it: a body
// on a contact that slid through the part before and ends this solve
// holding less friction than it could (static friction: the slip stopped)
// slipped for the share of the part that the friction used is of what
// kinetic friction gives, that friction being constant while it slips.
void DynamicsWorld::findSlipStops(const std::vector<Slip>& slipping) {
  slips_.clear();
  // Per contact: a body may slip on two at once (a cube under a rider on
  // the table), and one may stop while the other slips on. The points are
  // put in the order of their contacts' keys, each contact's in the order
  // slipping lists them (a contact of a compound may have several
  // manifolds, not listed together), and summed contact by contact.
  std::vector<std::pair<ContactKey, std::size_t>>& order = slipOrder_;
  order.clear();
  for (std::size_t i = 0; i < slipping.size(); ++i) order.emplace_back(contactOf(*slipping[i].manifold), i);
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<ContactKey, SlipUse>>& used = slipUse_;
  used.clear();
  for (const auto& [key, i] : order) {
    const auto& [manifold, point, velocity] = slipping[i];
    if (used.empty() || used.back().first != key) used.emplace_back(key, SlipUse{manifold});
    SlipUse& u = used.back().second;
    u.friction += std::hypot(point->m_appliedImpulseLateral1, point->m_appliedImpulseLateral2);
    u.limit += point->m_combinedFriction * point->m_appliedImpulse;
    if (point->m_appliedImpulse > 0) ++u.loaded;
    const btVector3 n = point->m_normalWorldOnB * point->m_appliedImpulse;
    u.normal += n.dot(u.normal) < 0 ? -n : n;
  }
  // A contact slides while its friction is at its limit. Only one that slid
  // through the part before, or into this one (slidIn), stops in it (a
  // slip that starts in a part, a rolling body's made by its rolling
  // resistance, is not one that stops); a body slipped for the share of
  // the part until the first of its contacts stopped.
  SlidingContacts& sliding = slidingNext_;
  sliding.clear();
  for (const auto& [key, u] : used) {
    if (!(u.limit > 0) || !(u.normal.length2() > 0)) continue;
    const bool through = u.friction >= (1.0 - kSlipShare) * u.limit;
    if (through) sliding.push_back(key);  // in order and once each, as `used` is
    const bool slidBefore = slid(sliding_, key) || slidIn(key);
    if (!through && !slidBefore) continue;
    // The friction that took back the rolling resistance's own slip is
    // not the slip's (below the limit: the slip stopped, so it is).
    double share = 1.0, taken = 0.0;
    if (!through) {
      if (const ResistedSlip* resisted = resistedSlip(key)) taken = std::min(resisted->friction, u.friction);
      share = (u.friction - taken) / (u.limit - taken);
    }
    for (const btCollisionObject* body : {u.manifold->getBody0(), u.manifold->getBody1()}) {
      if (body->isStaticOrKinematicObject()) continue;
      const bool face = u.loaded >= 3 && slidBefore;
      if (!face && through) continue;
      BodySlip& slip = slips_[body];
      if (face && u.limit > slip.faceLimit) {
        slip.face = {share, u.normal.normalized()};
        slip.faceLimit = u.limit;
      }
      if (!through && share < slip.stop.share) {
        slip.stop = {share, u.normal.normalized()};
        slip.stopTaken = taken;
      }
    }
  }
  std::swap(sliding_, slidingNext_);
  BodySet& settling = settling_[0];
  settling.clear();
  for (const auto& [body, slip] : slips_) {
    if (slip.stop.share < 1.0) settling.insert(body);
  }
}

}  // namespace tabletop
