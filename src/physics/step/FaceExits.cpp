#include "physics/step/FaceExits.h"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "physics/contact/ContactKinematics.h"
#include "physics/shapes/ShapeKinds.h"

namespace tabletop {
namespace {

// How far, m, a point may lie outside a box and still be on it (contact
// points are found a few nanometres apart), and how close to an edge a
// centre counts as on it.
constexpr double kOnBox = 1e-5;
constexpr double kOnEdge = 1e-9;

// A cut no shorter than this share of the part: a centre that close to the
// edge counts as on it (edgeBand).
constexpr double kShortestCut = 1e-3;

// The farthest a body may move across an edge in a part, as a share of its
// smallest half extent, for its lever there to be held at mid-part.
constexpr double kLeverTravel = 0.1;

// How near, m, an edge a centre moving across it at `speed` m/s counts as
// on it in a part `length` s long.
double edgeBand(double speed, double length) { return std::max(kOnEdge, kShortestCut * std::fabs(speed) * length); }

using BoxPiece = PointBoxes::Box;

// The box of `object` (itself, or a compound's child) that `point` lies on.
std::optional<BoxPiece> boxAt(const btCollisionObject& object, const btVector3& point) {
  const auto onIt = [&](const btCollisionShape* shape, const btTransform& place) -> std::optional<BoxPiece> {
    if (!isBox(*shape)) return std::nullopt;
    const btVector3 half = static_cast<const btBoxShape*>(shape)->getHalfExtentsWithMargin();
    const btVector3 local = place.invXform(point);
    for (int i = 0; i < 3; ++i) {
      if (std::fabs(local[i]) > half[i] + kOnBox) return std::nullopt;
    }
    return BoxPiece{place, half};
  };
  const btCollisionShape* shape = object.getCollisionShape();
  if (!shape->isCompound()) return onIt(shape, object.getWorldTransform());
  const auto* compound = static_cast<const btCompoundShape*>(shape);
  for (int c = 0; c < compound->getNumChildShapes(); ++c) {
    if (auto box = onIt(compound->getChildShape(c), object.getWorldTransform() * compound->getChildTransform(c))) {
      return box;
    }
  }
  return std::nullopt;
}

const btRigidBody* movingBody(const btCollisionObject* object) {
  const btRigidBody* body = btRigidBody::upcast(object);
  return body && !body->isStaticOrKinematicObject() && body->isActive() ? body : nullptr;
}

// The velocity of `body`'s centre relative to `support` there, in `box`'s frame.
btVector3 relativeVelocity(const btRigidBody& body, const btCollisionObject& support, const BoxPiece& box) {
  btVector3 v = body.getLinearVelocity();
  if (const btRigidBody* under = btRigidBody::upcast(&support)) {
    v -= under->getVelocityInLocalPoint(body.getCenterOfMassPosition() - under->getCenterOfMassPosition());
  }
  return box.place.getBasis().transpose() * v;
}

// A point where the body on side A (`carriedIsA`) or B of `manifold` rests
// on the upward face of a box of the other: the body, what carries it,
// that box, and which of the box's axes the face is across.
struct Carried {
  const btRigidBody* body;
  const btCollisionObject* support;
  const BoxPiece* box;  // PointBoxes' own, valid through the scan
  int face;
};
// Point `p` of manifold `m`.
std::optional<Carried> carriedOnFace(const btPersistentManifold& manifold, int m, int p, bool carriedIsA,
                                     PointBoxes& boxes) {
  const btManifoldPoint& point = manifold.getContactPoint(p);
  if (point.getDistance() > kOnBox) return std::nullopt;
  const btRigidBody* body = movingBody(carriedIsA ? manifold.getBody0() : manifold.getBody1());
  const btCollisionObject* support = carriedIsA ? manifold.getBody1() : manifold.getBody0();
  if (!body || body->getGravity().length2() == 0) return std::nullopt;
  // The normal points from B to A; carried from below, within 45 degrees.
  const btVector3 normal = carriedIsA ? point.m_normalWorldOnB : -point.m_normalWorldOnB;
  if (normal.dot(-body->getGravity().normalized()) < 0.7) return std::nullopt;
  const std::optional<BoxPiece>& box = boxes.at(manifold, m, p, carriedIsA ? 1 : 0);
  if (!box) return std::nullopt;
  const btVector3 local = box->place.getBasis().transpose() * normal;
  const int face = local.closestAxis();
  if (std::fabs(local[face]) < 0.999) return std::nullopt;  // an edge or a corner, not a face
  return Carried{body, support, &*box, face};
}

// Whether two carried points are of one body on one face of one box.
bool sameFace(const Carried& a, const Carried& b) {
  return a.body == b.body && a.support == b.support && a.face == b.face && a.box->place == b.box->place &&
         a.box->half == b.box->half;
}

}  // namespace

void PointBoxes::start(btDispatcher& dispatcher) {
  first_.resize(static_cast<std::size_t>(dispatcher.getNumManifolds()) + 1);
  std::size_t total = 0;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    first_[static_cast<std::size_t>(m)] = total;
    total += static_cast<std::size_t>(dispatcher.getManifoldByIndexInternal(m)->getNumContacts());
  }
  first_.back() = total;
  entries_.resize(total);
  for (Entry& e : entries_) e.known[0] = e.known[1] = false;
}

const std::optional<PointBoxes::Box>& PointBoxes::at(const btPersistentManifold& manifold, int m, int p, int side) {
  Entry& e = entries_[first_[static_cast<std::size_t>(m)] + static_cast<std::size_t>(p)];
  const btManifoldPoint& point = manifold.getContactPoint(p);
  const btVector3& place = side == 0 ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
  if (!e.known[side] || !(e.place[side] == place)) {
    e.box[side] = boxAt(side == 0 ? *manifold.getBody0() : *manifold.getBody1(), place);
    e.place[side] = place;
    e.known[side] = true;
  }
  return e.box[side];
}

double earliestFaceExit(btDispatcher& dispatcher, double horizon, PointBoxes& boxes, BodySet* eventful) {
  double earliest = horizon;
  // The time depends on the body, the box and the face alone, which the
  // points of a contact share: each is timed once.
  std::optional<Carried> timed;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      for (const bool carriedIsA : {true, false}) {  // either body may be the one carried
        const auto carried = carriedOnFace(manifold, m, p, carriedIsA, boxes);
        if (!carried || (timed && sameFace(*carried, *timed))) continue;
        timed = carried;
        const BoxPiece& box = *carried->box;
        const btVector3 centre = box.place.invXform(carried->body->getCenterOfMassPosition());
        const btVector3 v = relativeVelocity(*carried->body, *carried->support, box);
        for (int i = 0; i < 3; ++i) {
          if (i == carried->face || v[i] == 0) continue;
          const double left = box.half[i] - (v[i] > 0 ? centre[i] : -centre[i]);
          if (!(left > edgeBand(v[i], horizon))) continue;
          const double t = (left + kOnEdge) / std::fabs(v[i]);
          earliest = std::min(earliest, t);
          if (eventful && t < horizon) eventful->insert(carried->body), eventful->insert(carried->support);
        }
      }
    }
  }
  return earliest;
}

namespace {

// How a ball moves about what it touches at point `p` of manifold `m` in a
// part `length` s long, where its distance from it bends: the centre's
// place relative to the feature it moves about (an edge or corner of a
// box, or the other ball's centre) and its velocity relative to it, less
// any part along an edge; none over a box's face.
std::optional<std::pair<btVector3, btVector3>> curvedPath(const btPersistentManifold& manifold, int m, int p,
                                                       double length, PointBoxes& boxes) {
  const btRigidBody* a = movingBody(manifold.getBody0());
  const btRigidBody* b = movingBody(manifold.getBody1());
  if (isBall(*manifold.getBody0()) && isBall(*manifold.getBody1())) {
    if (!a && !b) return std::nullopt;
    const btVector3 r = manifold.getBody0()->getWorldTransform().getOrigin() -
                        manifold.getBody1()->getWorldTransform().getOrigin();
    const btVector3 v = (a ? a->getLinearVelocity() : btVector3(0, 0, 0)) - (b ? b->getLinearVelocity() : btVector3(0, 0, 0));
    return std::make_pair(r, v);
  }
  for (const bool ballIsA : {true, false}) {
    const btRigidBody* ball = ballIsA ? a : b;
    if (!ball || !isBall(*ball)) continue;
    const btCollisionObject& support = *(ballIsA ? manifold.getBody1() : manifold.getBody0());
    const std::optional<BoxPiece>& box = boxes.at(manifold, m, p, ballIsA ? 1 : 0);
    if (!box) continue;
    // The box's nearest point to the centre, sharp (its outer extents);
    // an axis the centre is past (or on the edge of) is pinned there.
    const btVector3 centre = box->place.invXform(ball->getCenterOfMassPosition());
    btVector3 v = relativeVelocity(*ball, support, *box);
    btVector3 nearest = centre;
    int pinned = 0;
    bool along[3] = {true, true, true};
    for (int i = 0; i < 3; ++i) {
      if (std::fabs(centre[i]) < box->half[i] - edgeBand(v[i], length)) continue;
      nearest[i] = std::copysign(box->half[i], centre[i]);
      along[i] = false;
      ++pinned;
    }
    if (pinned < 2) continue;  // over a face: the distance is linear in the motion
    for (int i = 0; i < 3; ++i) {
      if (along[i]) v[i] = 0;  // along an edge the distance does not change
    }
    return std::make_pair(centre - nearest, v);
  }
  return std::nullopt;
}

}  // namespace

void holdEdgeCurvature(btDispatcher& dispatcher, double length, double stepLength, bool meanVelocity,
                       std::vector<std::pair<btManifoldPoint*, btScalar>>& saved, PointBoxes& boxes) {
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      btManifoldPoint& point = manifold.getContactPoint(p);
      // A point striking now is an impact, which stops the closing at once.
      if (strikesNow(manifold, point, stepLength)) continue;
      const auto path = curvedPath(manifold, m, p, length, boxes);
      if (!path) continue;
      // How much farther apart the straight-line motion leaves them than
      // the row's first-order change: |r + v t| - |r| - (r / |r|).v t,
      // about v^2 t^2 / (2 |r|) for v across r.
      const auto& [r, v] = *path;
      const double reach = r.length();
      if (!(reach > 0)) continue;
      const double growth = (r + v * length).length() - reach - r.dot(v) / reach * length;
      if (!(growth > 0)) continue;
      // The gap the row sees: the end gap with the growth; with positions
      // that follow the mean velocity, as ImpactScan::holdMeanVelocity.
      const double gap = point.getDistance() + growth;
      const double mean = 2.0 * gap - closingSpeed(manifold, point) * length;
      saved.emplace_back(&point, point.getDistance());
      point.setDistance(meanVelocity && mean > gap ? mean : gap);
    }
  }
}

void holdEdgeLevers(btDispatcher& dispatcher, double length, std::vector<HeldPlace>& saved, PointBoxes& boxes) {
  constexpr double kOnSide = 1e-7;  // m: a clipped point lies on the edge to rounding
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      btManifoldPoint& point = manifold.getContactPoint(p);
      for (const bool carriedIsA : {true, false}) {
        const auto carried = carriedOnFace(manifold, m, p, carriedIsA, boxes);
        if (!carried) continue;
        const BoxPiece& box = *carried->box;
        const int face = carried->face;
        // Only a point on an edge of the support's face (most are inside
        // it: looked at first, as it costs the least).
        const btVector3 there = box.place.invXform(carriedIsA ? point.getPositionWorldOnB() : point.getPositionWorldOnA());
        bool onEdge = false;
        for (int i = 0; i < 3; ++i) onEdge = onEdge || (i != face && std::fabs(there[i]) >= box.half[i] - kOnSide);
        if (!onEdge) continue;
        const btVector3& onBody = carriedIsA ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
        const std::optional<BoxPiece>& own = boxes.at(manifold, m, p, carriedIsA ? 0 : 1);
        if (!own) continue;
        // A corner of the body's own box moves with it: only a point inside
        // its face, cut out by the support's edge, stays on that edge.
        const btVector3 mine = own->place.invXform(onBody);
        int corner = 0;
        for (int i = 0; i < 3; ++i) corner += std::fabs(mine[i]) >= own->half[i] - kOnSide ? 1 : 0;
        if (corner == 3) continue;
        const btVector3 v = relativeVelocity(*carried->body, *carried->support, box);
        btVector3 across(0, 0, 0);
        for (int i = 0; i < 3; ++i) {
          if (i != face && std::fabs(there[i]) >= box.half[i] - kOnSide) across[i] = v[i];
        }
        const double least = std::min({own->half.x(), own->half.y(), own->half.z()});
        if (across.length2() == 0 || across.length() * length > kLeverTravel * least) continue;
        const btVector3 back = box.place.getBasis() * across * (-0.5 * length);
        saved.push_back({&point, point.m_positionWorldOnA, point.m_positionWorldOnB});
        (carriedIsA ? point.m_positionWorldOnA : point.m_positionWorldOnB) += back;
      }
    }
  }
}

}  // namespace tabletop
