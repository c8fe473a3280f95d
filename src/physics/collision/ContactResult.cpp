#include "physics/collision/ContactResult.h"

#include <algorithm>
#include <functional>

#include "physics/collision/FlatFour.h"
#include "physics/shapes/ShapeKinds.h"

namespace tabletop {
namespace {

// The merge radius is this share of the smallest extent.
constexpr double kShareOfExtent = 0.5;

// The smallest extent of a shape's own bounding box, m (a plane's is huge).
double smallestExtent(const btCollisionShape& shape) {
  btTransform identity;
  identity.setIdentity();
  btVector3 low, high;
  shape.getAabb(identity, low, high);
  const btVector3 extent = high - low;
  return std::min({extent.x(), extent.y(), extent.z()});
}

// How far apart two points of one manifold are as features of a body (m,
// squared): on whichever body they lie nearer, a corner sliding over the
// floor or over another body stays the same corner of its own body, though
// it is a new place on the other every step. (A static body's side counts
// too: a point fixed there is the same place.)
double featureApart2(const btManifoldPoint& p, const btVector3& localA, const btVector3& localB) {
  return std::min((p.m_localPointA - localA).length2(), (p.m_localPointB - localB).length2());
}

// The kept point of `manifold` nearest `point` and within `radius` of it,
// on the moving body, or -1; none that `taken` says was found in this pass.
template <typename Taken>
int keptPointWithin(const btPersistentManifold& manifold, const btManifoldPoint& point, double radius,
                    const Taken& taken) {
  int nearest = -1;
  double nearestSquared = radius * radius;
  for (int p = 0; p < manifold.getNumContacts(); ++p) {
    if (taken(p)) continue;
    const double squared = featureApart2(manifold.getContactPoint(p), point.m_localPointA, point.m_localPointB);
    if (squared < nearestSquared) {
      nearestSquared = squared;
      nearest = p;
    }
  }
  return nearest;
}

// How far apart along the contact plane a point's two sides may slide
// before it is stale, metres: a point found in this step has none (to
// rounding); one kept from an earlier step has the two bodies' relative
// slide since. 1 um keeps the resting points of bodies that creep.
constexpr double kStaleDrift = 1e-6;

// A ball against a box meets the box's outer surface, sharp at its edges
// and corners. GJK rounds a box's edges by its margin (1 mm for the table
// top), so a ball rolled off the edge a millimetre early, and slid over the
// rounding with a tilted normal that pushed it on. From the ball's centre
// and the box, for a ball on either side of the pair: the normal on B, the
// point on B and the distance; false (GJK's point stands) unless the pair
// is a ball and a box with the centre outside the box.
bool ballOnSharpBox(const btCollisionObjectWrapper& a, const btCollisionObjectWrapper& b, btVector3& normalOnB,
                    btVector3& pointOnB, btScalar& depth) {
  const bool ballIsA = isBall(*a.getCollisionShape()) && isBox(*b.getCollisionShape());
  const bool ballIsB = isBall(*b.getCollisionShape()) && isBox(*a.getCollisionShape());
  if (!ballIsA && !ballIsB) return false;
  const btCollisionObjectWrapper& ball = ballIsA ? a : b;
  const btCollisionObjectWrapper& box = ballIsA ? b : a;
  const btScalar radius = static_cast<const btSphereShape*>(ball.getCollisionShape())->getRadius();
  const btVector3 half = static_cast<const btBoxShape*>(box.getCollisionShape())->getHalfExtentsWithMargin();
  const btTransform& place = box.getWorldTransform();
  const btVector3 centre = place.invXform(ball.getWorldTransform().getOrigin());
  btVector3 nearest = centre;
  for (int i = 0; i < 3; ++i) nearest[i] = std::clamp(centre[i], -half[i], half[i]);
  const btVector3 out = centre - nearest;
  const btScalar reach = out.length();
  if (!(reach > 0)) return false;  // the centre inside the box
  const btVector3 fromBox = place.getBasis() * (out / reach);  // world, box towards ball
  const btVector3 onBox = place * nearest;
  depth = reach - radius;
  normalOnB = ballIsA ? fromBox : -fromBox;
  pointOnB = ballIsA ? onBox : place.getBasis() * centre + place.getOrigin() - fromBox * radius;
  return true;
}

// What flatPointToReplace answers besides a point's index.
constexpr int kLeaveOut = -1;
constexpr int kBulletsChoice = -2;

// For a full manifold whose points and `added` all lie flat on one face
// (depths within kFlatDepths): which point `added` replaces, or kLeaveOut,
// keeping the four that span the largest area (on body A, where a face's
// points stay put); kBulletsChoice if they do not lie flat, for Bullet's
// own choice, which keeps the deepest. Bullet's weighs triangles
// as each point comes in: of the eight corners of the octagon where two
// equal cubes turned 3 degrees apart touch, it kept the four on one side
// of the centre, and the upper cube tipped at the first step (0.6 mm at
// 60 Hz). Where the depths differ, the deepest points hold the bodies
// apart and are kept: a widest four there dropped one end of a tipping
// box's edge, and a 3.5 kg cube on a 57 g box sprang up, 3 J gained.
int flatPointToReplace(const btPersistentManifold& manifold, const btManifoldPoint& added) {
  static_assert(MANIFOLD_CACHE_SIZE == 4, "a manifold keeps four points");
  const btManifoldPoint* points[MANIFOLD_CACHE_SIZE + 1];
  double lowest = added.getDistance(), highest = lowest;
  for (int p = 0; p < MANIFOLD_CACHE_SIZE; ++p) {
    points[p] = &manifold.getContactPoint(p);
    lowest = std::min<double>(lowest, points[p]->getDistance());
    highest = std::max<double>(highest, points[p]->getDistance());
  }
  if (highest - lowest > kFlatDepths) return kBulletsChoice;
  points[MANIFOLD_CACHE_SIZE] = &added;
  int best = MANIFOLD_CACHE_SIZE;
  double bestArea = -1.0;
  // Leaving `added` out first, so that a tie keeps the kept points.
  for (int out = MANIFOLD_CACHE_SIZE; out >= 0; --out) {
    const btVector3* corner[MANIFOLD_CACHE_SIZE];
    for (int p = 0, k = 0; p <= MANIFOLD_CACHE_SIZE; ++p) {
      if (p != out) corner[k++] = &points[p]->m_localPointA;
    }
    const double area = spannedArea(*corner[0], *corner[1], *corner[2], *corner[3]);
    if (area > bestArea) bestArea = area, best = out;
  }
  return best == MANIFOLD_CACHE_SIZE ? kLeaveOut : best;
}

}  // namespace

ContactResult::ContactResult(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                             FoundPoints& found, OfferedPoints& offered)
    : btManifoldResult(body0, body1), found_(found), offered_(offered) {
  found_.clear();
  offered_.clear();
}

double ContactResult::mergeRadius(const btCollisionShape& a, const btCollisionShape& b, double breakingThreshold) {
  return std::min(breakingThreshold, kShareOfExtent * std::min(smallestExtent(a), smallestExtent(b)));
}

double ContactResult::radiusFor(const btCollisionShape& a, const btCollisionShape& b, double breakingThreshold) {
  if (&a != radiusShapes_[0] || &b != radiusShapes_[1] || breakingThreshold != radiusThreshold_) {
    radiusShapes_[0] = &a, radiusShapes_[1] = &b;
    radiusThreshold_ = breakingThreshold;
    radius_ = mergeRadius(a, b, breakingThreshold);
  }
  return radius_;
}

void ContactResult::addContactPoint(const btVector3& foundNormal, const btVector3& foundPoint, btScalar foundDepth) {
  btPersistentManifold& manifold = *m_manifoldPtr;
  // The manifold's body A may be this result's body 1.
  const bool swapped = manifold.getBody0() != m_body0Wrap->getCollisionObject();
  const btCollisionObjectWrapper& a = swapped ? *m_body1Wrap : *m_body0Wrap;
  const btCollisionObjectWrapper& b = swapped ? *m_body0Wrap : *m_body1Wrap;
  btVector3 normalOnBInWorld = foundNormal, pointInWorld = foundPoint;
  btScalar depth = foundDepth;
  ballOnSharpBox(a, b, normalOnBInWorld, pointInWorld, depth);
  if (depth > manifold.getContactBreakingThreshold()) return;
  const btVector3 pointOnA = pointInWorld + normalOnBInWorld * depth;
  btManifoldPoint point(a.getCollisionObject()->getWorldTransform().invXform(pointOnA),
                        b.getCollisionObject()->getWorldTransform().invXform(pointInWorld), normalOnBInWorld,
                        depth);
  point.m_positionWorldOnA = pointOnA;
  point.m_positionWorldOnB = pointInWorld;

  // The pair's material, as Bullet combines it.
  const btCollisionObject* object0 = m_body0Wrap->getCollisionObject();
  const btCollisionObject* object1 = m_body1Wrap->getCollisionObject();
  point.m_combinedFriction = gCalculateCombinedFrictionCallback(object0, object1);
  point.m_combinedRestitution = gCalculateCombinedRestitutionCallback(object0, object1);
  point.m_combinedRollingFriction = gCalculateCombinedRollingFrictionCallback(object0, object1);
  point.m_combinedSpinningFriction = gCalculateCombinedSpinningFrictionCallback(object0, object1);
  const int flags = object0->getCollisionFlags() | object1->getCollisionFlags();
  if (flags & btCollisionObject::CF_HAS_CONTACT_STIFFNESS_DAMPING) {
    point.m_combinedContactDamping1 = gCalculateCombinedContactDampingCallback(object0, object1);
    point.m_combinedContactStiffness1 = gCalculateCombinedContactStiffnessCallback(object0, object1);
    point.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
  }
  if (flags & btCollisionObject::CF_HAS_FRICTION_ANCHOR) point.m_contactPointFlags |= BT_CONTACT_FLAG_FRICTION_ANCHOR;
  btPlaneSpace1(point.m_normalWorldOnB, point.m_lateralFrictionDir1, point.m_lateralFrictionDir2);
  point.m_partId0 = swapped ? m_partId1 : m_partId0;
  point.m_partId1 = swapped ? m_partId0 : m_partId1;
  point.m_index0 = swapped ? m_index1 : m_index0;
  point.m_index1 = swapped ? m_index0 : m_index1;
  offered_.offer(manifold, point);

  const auto foundNow = [&](int index) {
    const std::pair<const btPersistentManifold*, int> key(&manifold, index);
    return std::find(found_.begin(), found_.end(), key) != found_.end();
  };
  const int kept = keptPointWithin(
      manifold, point,
      radiusFor(*a.getCollisionShape(), *b.getCollisionShape(), manifold.getContactBreakingThreshold()),
      [&](int index) { return distinct_ && foundNow(index); });
  if (kept >= 0) {
    // Two points found in this pass and within the merge radius are one:
    // the deeper stays. Kept in the order found, a cube tipping over the
    // table's edge kept its near point on one side and its far point on
    // the other, and left the edge rolling.
    if (!distinct_ && foundNow(kept) && manifold.getContactPoint(kept).getDistance() <= depth) return;
    manifold.replaceContactPoint(point, kept);
    if (!foundNow(kept)) found_.emplace_back(&manifold, kept);
    return;
  }
  // Every kept point found in this pass, as the corners of a clipped face
  // are: the four to keep may be chosen among them all. (A point kept
  // from an earlier step goes on aging out as in Bullet.)
  const bool allFound = manifold.getNumContacts() == MANIFOLD_CACHE_SIZE && foundNow(0) && foundNow(1) &&
                        foundNow(2) && foundNow(3);
  const int replaced = allFound ? flatPointToReplace(manifold, point) : kBulletsChoice;
  if (replaced >= 0) {
    // A new point in the place of another: none of its impulses carried.
    manifold.getContactPoint(replaced) = point;
  } else if (replaced == kBulletsChoice) {
    const int added = manifold.addManifoldPoint(point);
    if (!foundNow(added)) found_.emplace_back(&manifold, added);
  }
}

void ContactResult::keepWidestFlatFour() {
  for (const OfferedPoints::Offers& offers : offered_.offers()) {
    auto& manifold = const_cast<btPersistentManifold&>(*offers.manifold);
    if (manifold.getNumContacts() != MANIFOLD_CACHE_SIZE) continue;
    bool allFound = true;
    for (int p = 0; p < MANIFOLD_CACHE_SIZE; ++p) {
      allFound = allFound && std::find(found_.begin(), found_.end(), std::make_pair(offers.manifold, p)) != found_.end();
    }
    std::array<int, 4> chosen;
    if (!allFound || !widestFour(offers, chosen)) continue;
    // A chosen point the manifold holds stays as it is; each other goes
    // in place of the nearest point not chosen, keeping its impulses and
    // age, as Bullet replaces a point (replaceContactPoint).
    bool slotChosen[MANIFOLD_CACHE_SIZE] = {false, false, false, false};
    std::array<bool, 4> placed = {false, false, false, false};
    for (int k = 0; k < 4; ++k) {
      const btVector3& place = offers.points[chosen[k]].m_localPointA;
      for (int p = 0; p < MANIFOLD_CACHE_SIZE && !placed[k]; ++p) {
        if (!slotChosen[p] && manifold.getContactPoint(p).m_localPointA == place) slotChosen[p] = placed[k] = true;
      }
    }
    for (int k = 0; k < 4; ++k) {
      if (placed[k]) continue;
      const btManifoldPoint& point = offers.points[chosen[k]];
      int nearest = -1;
      double nearestSquared = 0;
      for (int p = 0; p < MANIFOLD_CACHE_SIZE; ++p) {
        if (slotChosen[p]) continue;
        const double squared = featureApart2(manifold.getContactPoint(p), point.m_localPointA, point.m_localPointB);
        if (nearest < 0 || squared < nearestSquared) nearest = p, nearestSquared = squared;
      }
      manifold.replaceContactPoint(point, nearest);
      slotChosen[nearest] = true;
    }
  }
}

void CarriedImpulses::save(btDispatcher& dispatcher) {
  saved_.clear();
  ranges_.clear();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const std::size_t first = saved_.size();
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.m_appliedImpulse == 0 && point.m_appliedImpulseLateral1 == 0 && point.m_appliedImpulseLateral2 == 0) {
        continue;  // nothing to carry
      }
      saved_.push_back({manifold->getBody0(), manifold->getBody1(), point.m_localPointA, point.m_localPointB,
                        point.m_appliedImpulse, point.m_appliedImpulseLateral1, point.m_appliedImpulseLateral2,
                        point.getLifeTime()});
    }
    if (saved_.size() > first) ranges_.push_back({manifold, first, saved_.size() - first});
  }
  // The ranges by manifold, not the points: sorting every saved point was
  // an eighth of a step of a field of cubes at rest.
  std::sort(ranges_.begin(), ranges_.end(), [](const Range& a, const Range& b) {
    return std::less<const btPersistentManifold*>()(a.manifold, b.manifold);
  });
}

void CarriedImpulses::restore(btDispatcher& dispatcher) {
  if (saved_.empty()) return;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    std::vector<Saved*>& gone = gone_;
    gone.clear();
    const auto range = std::lower_bound(
        ranges_.begin(), ranges_.end(), manifold,
        [](const Range& r, const btPersistentManifold* key) { return std::less<const btPersistentManifold*>()(r.manifold, key); });
    if (range == ranges_.end() || range->manifold != manifold) continue;
    const auto first = saved_.begin() + static_cast<std::ptrdiff_t>(range->first);
    for (auto s = first; s != first + static_cast<std::ptrdiff_t>(range->count); ++s) {
      if (s->body0 != manifold->getBody0() || s->body1 != manifold->getBody1()) continue;
      bool kept = false;  // a kept or replaced point keeps its impulses exactly
      for (int p = 0; p < manifold->getNumContacts() && !kept; ++p) {
        const btManifoldPoint& point = manifold->getContactPoint(p);
        kept = point.m_appliedImpulse == s->impulse && point.m_appliedImpulseLateral1 == s->lateral1 &&
               point.m_appliedImpulseLateral2 == s->lateral2;
      }
      if (!kept) gone.push_back(&*s);
    }
    if (gone.empty()) continue;
    const double radius =
        ContactResult::mergeRadius(*manifold->getBody0()->getCollisionShape(),
                                   *manifold->getBody1()->getCollisionShape(), manifold->getContactBreakingThreshold());
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.m_appliedImpulse != 0 || point.m_appliedImpulseLateral1 != 0 || point.m_appliedImpulseLateral2 != 0) {
        continue;  // not made anew
      }
      auto nearest = gone.end();
      double nearestSquared = radius * radius;
      for (auto g = gone.begin(); g != gone.end(); ++g) {
        const double squared = featureApart2(point, (*g)->localA, (*g)->localB);
        if (squared < nearestSquared) nearestSquared = squared, nearest = g;
      }
      if (nearest == gone.end()) continue;
      point.m_appliedImpulse = (*nearest)->impulse;
      point.m_appliedImpulseLateral1 = (*nearest)->lateral1;
      point.m_appliedImpulseLateral2 = (*nearest)->lateral2;
      point.m_lifeTime = (*nearest)->lifeTime + (point.getLifeTime());
      gone.erase(nearest);
    }
  }
  saved_.clear();
}

void dropDriftedPoints(btPersistentManifold& manifold) {
  for (int p = manifold.getNumContacts() - 1; p >= 0; --p) {
    const btManifoldPoint& point = manifold.getContactPoint(p);
    const btVector3 apart = point.getPositionWorldOnA() - point.getPositionWorldOnB();
    const btVector3 slide = apart - point.m_normalWorldOnB * point.m_normalWorldOnB.dot(apart);
    if (slide.length2() > kStaleDrift * kStaleDrift) manifold.removeContactPoint(p);
  }
}

}  // namespace tabletop
