#include "physics/step/RollingLines.h"

#include <cmath>

#include "physics/contact/ContactKinematics.h"
#include "physics/shapes/RoundEnds.h"

namespace tabletop {
namespace {

// Bounds of what counts as a line of contact and as rolling about it.
constexpr double kShortest = 1e-3;     // m, between the line's ends
constexpr double kOffLine = 1e-3;      // of its length: a point's distance from it
constexpr double kSameNormal = 1e-6;   // 1 - cos, between the points' normals
constexpr int kMostPoints = 8;
constexpr double kRolls = 1e-2;        // of the spin: slip at the ends, spin across
// A line turning by more than this in a part (rad) has jumped, not turned;
// one meeting the old farther than this many lengths away has moved along.
constexpr double kMostTurn = 0.5;
constexpr double kFarthest = 100.0;
// An axis closer to level than this (the cosine of its angle with the
// normal) meets the support too far off: a cylinder's line moves along.
constexpr double kLevelAxis = 1e-3;
// An axis this close to the normal (the sine of their angle) stands up:
// its points on a line are a chord of a rim, not a generator.
constexpr double kUpright = 1e-3;

bool byBody(const btCollisionObject* x, const btCollisionObject* y) { return std::less<>()(x, y); }

// Whether a body may be a solid of revolution (roundEnds() says which
// are): a moving cylinder or hull. Boxes, cubes and balls are not.
bool mayRoll(const btCollisionObject& o) {
  const int type = o.getCollisionShape()->getShapeType();
  return !o.isStaticOrKinematicObject() && (type == CYLINDER_SHAPE_PROXYTYPE || type == CONVEX_HULL_SHAPE_PROXYTYPE);
}

}  // namespace

// The line of one body's touching points [from, to), if they make one.
bool RollingLines::lineOf(const Touch* from, const Touch* to, RollingLines::Line& line) {
  const auto count = to - from;
  if (count < 2 || count > kMostPoints) return false;
  btVector3 normal(0, 0, 0);
  for (const Touch* t = from; t != to; ++t) {
    if (t->other != from->other || t->normal.dot(from->normal) < 1 - kSameNormal) return false;
    normal += t->normal;
  }
  const Touch* a = from;
  const Touch* b = from + 1;
  for (const Touch* i = from; i != to; ++i) {
    for (const Touch* j = i + 1; j != to; ++j) {
      if (i->point.distance2(j->point) > a->point.distance2(b->point)) a = i, b = j;
    }
  }
  const btVector3 along = b->point - a->point;
  const double length = along.length();
  if (length < kShortest) return false;
  const btVector3 unit = along / length;
  for (const Touch* t = from; t != to; ++t) {
    if (unit.cross(t->point - a->point).length() > kOffLine * length) return false;
  }
  // A generator of a solid of revolution: in the plane of its axis and
  // the normal, the axis off the normal.
  const auto* body = static_cast<const btRigidBody*>(from->body);
  const btVector3 across = normal.normalized().cross(body->getWorldTransform().getBasis().getColumn(1));
  if (!roundEnds(*body->getCollisionShape()) || across.length() < kUpright) return false;
  if (std::abs(unit.dot(across)) > kOffLine * across.length()) return false;
  line = Line{from->body, from->other, a->point, b->point, normal.normalized(), body->getCenterOfMassPosition()};
  return true;
}

namespace {

// `u` less its part along `n`, unit.
btVector3 flat(const btVector3& u, const btVector3& n) {
  const btVector3 v = u - n * u.dot(n);
  const double size = v.length();
  return size > kShortest * kOffLine ? v / size : btVector3(0, 0, 0);
}

}  // namespace

const std::vector<RollingLines::Line>& RollingLines::findLines(btDispatcher& dispatcher) {
  std::vector<Line>& out = lines_;
  std::vector<Touch>& touches = touches_;
  out.clear();
  touches.clear();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() > kLoadTouching) continue;
      if (mayRoll(*a)) touches.push_back({a, b, point.getPositionWorldOnA(), point.m_normalWorldOnB});
      if (mayRoll(*b)) touches.push_back({b, a, point.getPositionWorldOnB(), -point.m_normalWorldOnB});
    }
  }
  std::stable_sort(touches.begin(), touches.end(), [](const Touch& x, const Touch& y) { return byBody(x.body, y.body); });
  for (std::size_t i = 0; i < touches.size();) {
    std::size_t j = i;
    while (j < touches.size() && touches[j].body == touches[i].body) ++j;
    Line line;
    if (lineOf(touches.data() + i, touches.data() + j, line)) out.push_back(line);
    i = j;
  }
  return out;
}

bool RollingLines::rollsAbout(const btRigidBody& body, const Line& line) {
  const btVector3 spin = body.getAngularVelocity();
  const btVector3 linear = body.getLinearVelocity();
  const double rate = spin.length();
  const double length = line.a.distance(line.b);
  if (rate <= 0) return false;
  const btVector3 unit = (line.b - line.a) / length;
  const double slip = kRolls * rate * length;
  return spin.cross(unit).length() <= kRolls * rate &&
         (linear + spin.cross(line.a - line.centre)).length() <= slip &&
         (linear + spin.cross(line.b - line.centre)).length() <= slip;
}

void RollingLines::record(btDispatcher& dispatcher, const BodySet& aside) {
  std::vector<Line> kept;
  for (const Line& r : recorded_) {
    if (aside.contains(r.body)) kept.push_back(r);
  }
  recorded_.clear();
  turns_.clear();
  for (const Line& line : findLines(dispatcher)) {
    const auto& body = *static_cast<const btRigidBody*>(line.body);
    if (aside.contains(line.body) || !rollsAbout(body, line)) continue;
    const double length = line.a.distance(line.b);
    recorded_.push_back(line);
    // It turns about where its axis meets the support (none for a level axis).
    const btVector3 axis = body.getWorldTransform().getBasis().getColumn(1);
    if (std::abs(axis.dot(line.normal)) < kLevelAxis) continue;
    const btVector3 origin = body.getWorldTransform().getOrigin();
    const btVector3 centre = origin + axis * (line.normal.dot(line.a - origin) / line.normal.dot(axis));
    if (centre.distance(line.a) > kFarthest * length) continue;
    turns_.push_back({line.body, centre, line.normal, axis});
  }
  if (kept.empty()) return;
  recorded_.insert(recorded_.end(), kept.begin(), kept.end());
  std::stable_sort(recorded_.begin(), recorded_.end(),
                   [](const Line& x, const Line& y) { return byBody(x.body, y.body); });
}

const std::vector<btRigidBody*>& RollingLines::transport(btDispatcher& dispatcher, const BodySet& kicked) {
  moved_.clear();
  rolling_.clear();
  for (const Line& now : findLines(dispatcher)) {
    if (kicked.contains(now.body)) continue;
    auto* body = static_cast<btRigidBody*>(const_cast<btCollisionObject*>(now.body));
    const auto found = std::lower_bound(recorded_.begin(), recorded_.end(), now.body,
                                        [](const Line& r, const btCollisionObject* key) { return byBody(r.body, key); });
    if (found == recorded_.end() || found->body != now.body) {
      // Not rolling on a line before (a scene's start): rolling on it now.
      if (rollsAbout(*body, now)) rolling_.push_back(body);
      continue;
    }
    const Line& was = *found;
    const btVector3& n = now.normal;
    if (was.support != now.support || was.normal.dot(n) < 1 - kSameNormal) continue;
    const btVector3 d0 = flat(was.b - was.a, n);
    btVector3 d1 = flat(now.b - now.a, n);
    if (d0.fuzzyZero() || d1.fuzzyZero()) continue;
    if (d0.dot(d1) < 0) d1 = -d1;
    const double turn = std::atan2(n.dot(d0.cross(d1)), d0.dot(d1));
    if (std::abs(turn) < 1e-9 || std::abs(turn) > kMostTurn) continue;
    // The old line and the new meet in the support's plane where the line
    // turned about: far off, it moved along rather than turned.
    const btVector3 gap = now.a - was.a;
    const double s = n.dot((gap - n * gap.dot(n)).cross(d1)) / n.dot(d0.cross(d1));
    const btVector3 centre = was.a + d0 * s;
    if (centre.distance(now.a) > kFarthest * now.a.distance(now.b)) continue;
    // The velocity it rolled with, turned as the line turned: its spin,
    // and at the line's middle the old middle's velocity (none, rolling).
    const btQuaternion q(n, turn);
    const btVector3 spin = body->getAngularVelocity();
    const btVector3 oldMiddle = (was.a + was.b) / 2, middle = (now.a + now.b) / 2;
    const btVector3 atMiddle = quatRotate(q, body->getLinearVelocity() + spin.cross(oldMiddle - was.centre));
    const btVector3 turned = quatRotate(q, spin);
    body->setAngularVelocity(turned);
    body->setLinearVelocity(atMiddle + turned.cross(body->getCenterOfMassPosition() - middle));
    moved_.push_back(body);
    rolling_.push_back(body);
  }
  return moved_;
}

bool RollingLines::turnAt(const btRigidBody& body, const btTransform& start, const btVector3& linear,
                          const btVector3& spin, double dt, btTransform& pose) const {
  const auto found = std::lower_bound(turns_.begin(), turns_.end(), &body,
                                      [](const Turn& t, const btCollisionObject* key) { return byBody(t.body, key); });
  if (found == turns_.end() || found->body != &body) return false;
  const Turn& t = *found;
  // The mean spin as the axis's precession about the normal and the
  // solid's spin about its own axis (both through the centre), and what
  // is left of it across them. Precession after spin, each at its mean
  // rate, is the rolling motion itself: turned about one line, however
  // chosen, the body tilted by the cube of its turn.
  const double c = t.normal.dot(t.axis);
  const double across = spin.dot(t.normal), along = spin.dot(t.axis);
  const double precession = (across - c * along) / (1 - c * c);
  const double own = (along - c * across) / (1 - c * c);
  const btVector3 rest = spin - t.normal * precession - t.axis * own;
  const btVector3 turnOwn = t.axis * own + rest;
  const double ownAngle = turnOwn.length() * dt;
  const btQuaternion first = ownAngle > 0 ? btQuaternion(turnOwn / turnOwn.length(), ownAngle) : btQuaternion::getIdentity();
  const btQuaternion second(t.normal, precession * dt);
  const btQuaternion turn = second * first;
  const btVector3 x = start.getOrigin();
  const btVector3 atCentre = linear + spin.cross(t.centre - x);
  pose.setOrigin(t.centre + quatRotate(turn, x - t.centre) + atCentre * dt);
  pose.setRotation((turn * start.getRotation()).normalized());
  return true;
}

void RollingLines::putBack(const BodySet& only) {
  std::vector<Line> kept;
  for (const Line& r : recorded_) {
    if (!only.contains(r.body)) kept.push_back(r);
  }
  for (const Line& r : saved_) {
    if (only.contains(r.body)) kept.push_back(r);
  }
  std::stable_sort(kept.begin(), kept.end(), [](const Line& x, const Line& y) { return byBody(x.body, y.body); });
  recorded_ = std::move(kept);
}

}  // namespace tabletop
