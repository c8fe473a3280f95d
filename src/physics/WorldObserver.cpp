// World's observer: after each step it reads the contact manifolds and
// every entity's motion, and updates what the report and the events are
// about: who touches whom, what holds each entity up, the drop test (report
// 3.4), rest. Split from World.cpp, which builds and steps the scene.

#include <algorithm>
#include <cmath>

#include "physics/World.h"

namespace tabletop {
namespace {

// Two entities start touching when a contact point comes within
// kTouchDistance, and part only once every point is beyond kApartDistance,
// so two cubes sliding together do not flicker in and out of contact.
constexpr double kTouchDistance = 1e-4;  // m
constexpr double kApartDistance = 1e-3;  // m
// A body in the air whose bottom is this close under the table top still
// hangs over it (startStatus).
constexpr double kOverTopSlack = 1e-6;  // m
// A contact supports an entity when its normal points up within 60 degrees.
constexpr double kSupportNormalY = 0.5;
// An entity's support stays what it was while that still pushes it up with
// at least this share of the hardest push: a cube resting across two
// others, each carrying half, would otherwise change support (and "land")
// whenever rounding tips the balance.
constexpr double kKeepSupportShare = 0.1;

}  // namespace

// Nothing is judged at rest before the first look at the scene (start()),
// which sees the starting velocities and what holds each body up.
bool World::allAtRest() const {
  if (!started_) return false;
  for (const Tracker& t : trackers_) {
    if (!t.atRest) return false;
  }
  return true;
}

// Reads the contact manifolds and every entity's motion after a step, and
// records what changed. With `emit` false (the initial state) it only sets
// the state.
double World::landingTime(const Tracker& tracker, const Shape& shape, int support) const {
  // The height its centre has when it rests flat on the support's top.
  double top = table_.topHeight();
  if (participant(support).kind() == Support::Kind::Ground) top = 0.0;
  if (support >= 0) {
    const Shape& base = *entities_[static_cast<std::size_t>(support)];
    top = base.position().y() + base.above();
  }
  const double contact = top + shape.below();
  // Falling freely from the step's start: y0 + vy0 t - g t^2 / 2 = contact.
  const double y0 = tracker.lastCentre.y(), vy0 = tracker.lastVelocity.y(), g = settings_.gravity;
  const double dt = settings_.timestep, start = time_ - dt;
  const double disc = vy0 * vy0 + 2.0 * g * (y0 - contact);
  if (g <= 0.0 || disc < 0.0) return time_;
  return start + std::clamp((vy0 + std::sqrt(disc)) / g, 0.0, dt);
}

std::optional<double> World::firstStruck(int entity, int other) const {
  const std::pair<int, int> key{std::min(entity, other), std::max(entity, other)};
  const auto at = std::lower_bound(struckTimes_.begin(), struckTimes_.end(), key,
                                   [](const StruckTime& s, const std::pair<int, int>& k) { return s.pair < k; });
  if (at == struckTimes_.end() || at->pair != key) return std::nullopt;
  return time_ - settings_.timestep + at->at;
}

// The pairs struck in the last step, by pair and then time, so that
// firstStruck finds a pair's first by bisection.
void World::sortStruck() {
  struckTimes_.clear();
  for (const DynamicsWorld::Struck& pair : struck_) {
    const int a = pair.a->getUserIndex(), b = pair.b->getUserIndex();
    struckTimes_.push_back({{std::min(a, b), std::max(a, b)}, pair.at});
  }
  std::sort(struckTimes_.begin(), struckTimes_.end(), [](const StruckTime& x, const StruckTime& y) {
    return x.pair != y.pair ? x.pair < y.pair : x.at < y.at;
  });
}

// Reads the contact manifolds and every entity's motion after a step, and
// records what changed. With `emit` false (the initial state) it only sets
// the state. Each entity's support, edge and rest are judged in turn, so
// events of one time keep the entities' order.
void World::observe(bool emit) {
  gatherContacts();
  observeTouching(emit);
  findSupports();
  // The first look: where each entity starts, on the table or never on it.
  for (std::size_t i = 0; !emit && i < entities_.size(); ++i) {
    Shape& shape = *entities_[i];
    const btVector3 c = shape.position();
    const bool over = overTableTop(toVec3(c), c.y() - shape.below(), table_.edges(), table_.topHeight(), kOverTopSlack);
    shape.setStatus(startStatus(heldBy(i), over));
  }
  for (std::size_t i = 0; i < entities_.size(); ++i) {
    observeSupport(i, emit);
    observeEdge(i, emit);
    observeRest(i, emit);
  }
}

// Contacts, one entry per (entity, other body) pair and side: how close
// they are, and how hard the other pushes the entity up. Entries are
// merged by sorting, in a buffer kept from step to step.
void World::gatherContacts() {
  contacts_.clear();
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    const int a = manifold->getBody0()->getUserIndex();
    const int b = manifold->getBody1()->getUserIndex();
    // A manifold left without points, its drifted ones dropped as two
    // boxes part while sliding (DynamicsWorld), holds a pair Bullet still
    // sees as near: it counts as at the parting distance, so a pair that
    // was touching stays so and one that was not does not begin.
    if (manifold->getNumContacts() == 0) {
      if (a >= 0) contacts_.push_back({a, b, kApartDistance, -1.0});
      if (b >= 0) contacts_.push_back({b, a, kApartDistance, -1.0});
    }
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      const double distance = point.getDistance();
      const bool touching = distance <= kTouchDistance;
      // The normal on B points from B towards A.
      const double up = point.m_normalWorldOnB.y();
      const double impulse = point.getAppliedImpulse();
      if (a >= 0) contacts_.push_back({a, b, distance, touching && up > kSupportNormalY ? impulse : -1.0});
      if (b >= 0) contacts_.push_back({b, a, distance, touching && -up > kSupportNormalY ? impulse : -1.0});
    }
  }
  // A pair that struck inside the step touched then, though it may be
  // apart by its end: a ball bouncing off the floor landed on it. It holds
  // the entity up with no load, so it is the support only where nothing
  // else pushes.
  for (const DynamicsWorld::Struck& pair : struck_) {
    const int a = pair.a->getUserIndex(), b = pair.b->getUserIndex();
    const double up = pair.normalOnB.y();
    if (a >= 0) contacts_.push_back({a, b, 0.0, up > kSupportNormalY ? 0.0 : -1.0});
    if (b >= 0) contacts_.push_back({b, a, 0.0, -up > kSupportNormalY ? 0.0 : -1.0});
  }
  // By entity and other: counted out by entity, then each entity's few
  // sorted by the other body, linear in the entries (one sort of them all
  // was a tenth of a step of a field of cubes).
  std::vector<std::size_t>& end = contactEnds_;
  end.assign(entities_.size() + 1, 0);
  for (const Contact& c : contacts_) ++end[static_cast<std::size_t>(c.entity) + 1];
  for (std::size_t i = 1; i < end.size(); ++i) end[i] += end[i - 1];
  byEntity_.resize(contacts_.size());
  for (const Contact& c : contacts_) byEntity_[end[static_cast<std::size_t>(c.entity)]++] = c;
  for (std::size_t i = 0; i < entities_.size(); ++i) {
    const auto first = byEntity_.begin() + static_cast<std::ptrdiff_t>(i == 0 ? 0 : end[i - 1]);
    const auto last = byEntity_.begin() + static_cast<std::ptrdiff_t>(end[i]);
    if (last - first > 1) std::sort(first, last, [](const Contact& x, const Contact& y) { return x.other < y.other; });
  }
  contacts_.swap(byEntity_);
  // Merge: the closest distance, and the summed upward impulse (or -1 when
  // the other body does not hold the entity up).
  std::size_t merged = 0;
  for (std::size_t k = 0; k < contacts_.size(); ++k) {
    Contact& c = contacts_[k];
    if (merged > 0 && contacts_[merged - 1].entity == c.entity && contacts_[merged - 1].other == c.other) {
      Contact& into = contacts_[merged - 1];
      into.distance = std::min(into.distance, c.distance);
      if (c.support >= 0) into.support = std::max(into.support, 0.0) + c.support;
    } else {
      contacts_[merged++] = c;
    }
  }
  contacts_.resize(merged);
}

Support::Kind World::heldBy(std::size_t i) const {
  // A loop of entities holding each other up holds nothing up.
  int s = supports_[i];
  for (std::size_t hops = 0; s >= 0 && hops < entities_.size(); ++hops) s = supports_[static_cast<std::size_t>(s)];
  return s == kNoSupport || s >= 0 ? Support::Kind::None : participant(s).kind();
}

// Which entity pairs touch: a pair starts touching within kTouchDistance and
// parts only beyond kApartDistance; a pair that starts is an event.
void World::observeTouching(bool emit) {
  // contacts_ is sorted by entity and other, so the pairs come in order.
  std::vector<std::pair<int, int>>& touching = touchingNow_;
  touching.clear();
  if (emit) sortStruck();
  for (const Contact& c : contacts_) {
    if (c.other < 0 || c.entity > c.other) continue;  // each entity pair once
    const auto pair = std::make_pair(c.entity, c.other);
    const bool was = std::binary_search(touching_.begin(), touching_.end(), pair);
    if (c.distance <= kTouchDistance || (was && c.distance <= kApartDistance)) {
      touching.push_back(pair);
      if (emit && !was) {
        Event e;
        e.t = firstStruck(pair.first, pair.second).value_or(time_);
        e.type = EventType::ContactBegin;
        e.entity = entities_[pair.first]->name();
        e.other = entities_[pair.second]->name();
        record(e);
      }
    }
  }
  touching_.swap(touching);
}

// Support: the body pushing each entity up hardest (ties: the lower
// index, the table and ground first), or the one before while it still
// pushes with kKeepSupportShare of that.
void World::findSupports() {
  const std::size_t n = entities_.size();
  std::vector<int>& support = supports_;
  std::vector<double>& strongest = strongest_;
  std::vector<double>& current = currentPush_;
  support.assign(n, kNoSupport);
  strongest.assign(n, -1.0);
  current.assign(n, -1.0);
  for (const Contact& c : contacts_) {
    if (c.support > strongest[c.entity]) {
      strongest[c.entity] = c.support;
      support[c.entity] = c.other;
    }
    if (c.other == trackers_[static_cast<std::size_t>(c.entity)].support) current[c.entity] = c.support;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (current[i] >= 0 && current[i] >= kKeepSupportShare * strongest[i]) support[i] = trackers_[i].support;
  }
}

// A support after none that is not the last one means the entity
// landed. A body that moves from one support to another without leaving
// them (a cube that lands across two, the first to touch it carrying
// nothing, the other all of its weight) has not.
void World::observeSupport(std::size_t i, bool emit) {
  Shape& shape = *entities_[i];
  Tracker& tracker = trackers_[i];
  const std::vector<int>& support = supports_;
  if (support[i] != tracker.support) {
    const bool airborne = tracker.support == kNoSupport;
    tracker.support = support[i];
    shape.setSupport(support[i] == kNoSupport ? Support() : participant(support[i]));
    if (support[i] != kNoSupport) {
      if (emit && airborne && support[i] != tracker.lastSupport) {
        Event e;
        e.t = landingTime(tracker, shape, support[i]);
        e.type = EventType::Lands;
        e.entity = shape.name();
        e.on = shape.support();
        record(e);
      }
      tracker.lastSupport = support[i];
    }
  }
}

// Report 3.4: the centre passing an edge starts the drop, at the time
// inside the step at which it passed.
void World::observeEdge(std::size_t i, bool emit) {
  Shape& shape = *entities_[i];
  Tracker& tracker = trackers_[i];
  if (shape.checkBoundary(table_) && emit) {
    const double dt = settings_.timestep;
    Event e;
    e.t = time_ - dt + dt * edgeCrossing(toVec3(tracker.lastCentre), toVec3(tracker.lastVelocity), toVec3(shape.position()), dt,
                                         shape.status(), table_.edges());
    e.type = EventType::LeavesTable;
    e.entity = shape.name();
    e.edge = dropEdge(shape.status());
    record(e);
  }
}

// Rest: slow for a whole window; the event carries the window's start.
// The drop ends once the entity is at rest below the table top.
void World::observeRest(std::size_t i, bool emit) {
  Shape& shape = *entities_[i];
  Tracker& tracker = trackers_[i];
  const std::vector<int>& support = supports_;
  const btRigidBody* body = shape.body();
  const bool slow = body->getLinearVelocity().length() < kRestSpeed &&
                    body->getAngularVelocity().length() < kRestSpin;
  if (!slow) {
    tracker.quietSince = -1.0;
    tracker.atRest = false;
  } else if (!emit) {
    // At the start, a slow body is at rest only where something holds it
    // up: one placed in mid-air is about to fall.
    tracker.atRest = support[i] != kNoSupport;
  } else {
    if (tracker.quietSince < 0.0) tracker.quietSince = time_;
    if (!tracker.atRest && time_ - tracker.quietSince >= kRestWindow - 1e-12) {
      tracker.atRest = true;
      Event e;
      e.t = tracker.quietSince;
      e.type = EventType::AtRest;
      e.entity = shape.name();
      record(e);
    }
  }

  // The status rule (EntityPositionStatus.h): down means at rest, and for
  // a drop also below the table top.
  const EntityPositionStatus s = shape.status();
  const bool down = tracker.atRest && (neverOnTable(s) || shape.position().y() < table_.topHeight());
  shape.setStatus(comeDown(s, down, down && neverOnTable(s) && heldBy(i) == Support::Kind::Table));
}

std::vector<std::pair<Support, Support>> World::overlaps(double tolerance) {
  addLegsIfReachable();
  world_->performDiscreteCollisionDetection();
  std::vector<std::pair<Support, Support>> found;
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      if (manifold->getContactPoint(p).getDistance() < -tolerance) {
        found.emplace_back(participant(manifold->getBody0()), participant(manifold->getBody1()));
        break;
      }
    }
  }
  return found;
}

double World::deepestPenetration() const {
  double deepest = 0.0;
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      deepest = std::max(deepest, double(-manifold->getContactPoint(p).getDistance()));
    }
  }
  return deepest;
}

std::vector<ContactReport> World::contacts() const {
  // A point counts while it is within Bullet's contact breaking threshold
  // of touching; it is reported midway between the two surfaces, an entity
  // first (Bullet's normal points from its second body to its first).
  constexpr double kShownWithin = 1e-3;  // metres
  std::vector<ContactReport> out;
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    const bool swap = manifold->getBody0()->getUserIndex() < 0;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() > kShownWithin) continue;
      ContactReport c;
      c.a = participant(swap ? manifold->getBody1() : manifold->getBody0());
      c.b = participant(swap ? manifold->getBody0() : manifold->getBody1());
      c.point = toVec3(0.5 * (point.getPositionWorldOnA() + point.getPositionWorldOnB()));
      c.normal = toVec3(swap ? -point.m_normalWorldOnB : point.m_normalWorldOnB);
      c.depth = -point.getDistance();
      c.impulse = point.getAppliedImpulse();
      out.push_back(c);
    }
  }
  return out;
}

std::vector<BodyMotion> World::motions() const {
  std::vector<BodyMotion> out;
  out.reserve(entities_.size());
  for (const auto& e : entities_) {
    const btRigidBody* body = e->body();
    const btQuaternion q = body->getWorldTransform().getRotation();
    out.push_back({toVec3(body->getWorldTransform().getOrigin()),
                   {q.w(), q.x(), q.y(), q.z()},
                   toVec3(body->getLinearVelocity()),
                   toVec3(body->getAngularVelocity())});
  }
  return out;
}

std::vector<EntityState> World::snapshot() const {
  const std::vector<BodyMotion> moving = motions();
  std::vector<EntityState> states;
  states.reserve(entities_.size());
  for (std::size_t i = 0; i < entities_.size(); ++i) {
    const Shape& e = *entities_[i];
    EntityState s;
    s.name = e.name();
    s.shape = e.kind();
    s.position = moving[i].position;
    s.orientation = moving[i].orientation;
    s.yawDegrees = e.yawDegrees();
    s.linearVelocity = moving[i].linearVelocity;
    s.angularVelocity = moving[i].angularVelocity;
    s.status = e.status();
    s.support = e.support();
    states.push_back(s);
  }
  return states;
}

}  // namespace tabletop
