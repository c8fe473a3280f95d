#include "physics/World.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/Angle.h"
#include "physics/ContactMaterial.h"
#include "physics/StepPush.h"

namespace tabletop {
namespace {

// Body user indices: entities use their index; these mark the rest.
constexpr int kTableIndex = -2;
constexpr int kGroundIndex = -3;

// Two entities start touching when a contact point comes within
// kTouchDistance, and part only once every point is beyond kApartDistance,
// so two cubes sliding together do not flicker in and out of contact.
constexpr double kTouchDistance = 1e-4;  // m
constexpr double kApartDistance = 1e-3;  // m
// A contact supports an entity when its normal points up within 60 degrees.
constexpr double kSupportNormalY = 0.5;
// An entity is at rest once slower than these for kRestWindow seconds.
constexpr double kRestSpeed = 5e-3;   // m/s
constexpr double kRestSpin = 5e-2;    // rad/s
constexpr double kRestWindow = 0.1;   // s
// How far an entity may move in one part of a step, as a share of its
// smallest half extent (World::substeps).
constexpr double kSubstepTravel = 0.5;

btVector3 toBullet(const Vec3& v) { return btVector3(v.x, v.y, v.z); }
Vec3 toVec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

btQuaternion yawRotation(double degrees) {
  return btQuaternion(btVector3(0, 1, 0), convertAngle(degrees));
}

// Bullet's rigid-body flags for the gyroscopic term (Settings::gyroscopic).
constexpr int kGyroscopicFlags = BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT | BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD |
                                 BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY;

int gyroscopicFlag(Gyroscopic g) {
  switch (g) {
    case Gyroscopic::None: return 0;
    case Gyroscopic::Explicit: return BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT;
    case Gyroscopic::ImplicitWorld: return BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD;
    case Gyroscopic::ImplicitBody: return BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY;
  }
  return BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY;
}

}  // namespace

World::World(const Settings& settings, const TableSpec& table, const Material& ground)
    : settings_(settings),
      pipeline_(settings, table),
      dispatcher_(pipeline_.dispatcher.get()),
      world_(pipeline_.world.get()),
      table_(table, settings.legsWhenReachable),
      ground_(ground, settings.floorPairsNearFloor) {
  updateSmoothAcceleration();
  // The legs, when separate, are the table too: its material, its name.
  for (btRigidBody* part : {&table_.body(), table_.legsBody()}) {
    if (!part) continue;
    part->setUserPointer(const_cast<Material*>(&table_.spec().material));
    part->setUserIndex(kTableIndex);
  }
  ground_.body().setUserPointer(const_cast<Material*>(&ground_.material()));
  ground_.body().setUserIndex(kGroundIndex);
  world_->addRigidBody(&table_.body());
  world_->addRigidBody(&ground_.body());
}

World::~World() {
  for (auto& e : entities_) world_->removeRigidBody(e->body());
  if (legsIn_) world_->removeRigidBody(table_.legsBody());
  world_->removeRigidBody(&ground_.body());
  world_->removeRigidBody(&table_.body());
}

// The legs stand under the top: a body reaches them only from below its
// underside. They join the world, for good, before the first step in
// which some body's box could come down that far: its lowest point, less
// the distance it can fall in a step and Bullet's contact breaking
// threshold, is below the underside.
void World::addLegsIfReachable() {
  if (legsIn_ || !table_.legsBody()) return;
  const double underside = table_.undersideHeight();
  const double dt = settings_.timestep;
  for (const auto& e : entities_) {
    const btRigidBody* body = e->body();
    btVector3 low, high;
    body->getCollisionShape()->getAabb(body->getWorldTransform(), low, high);
    const double fall = (std::max(0.0, -body->getLinearVelocity().y()) + settings_.gravity * dt) * dt;
    if (low.y() - fall - gContactBreakingThreshold < underside) {
      world_->addRigidBody(table_.legsBody());
      legsIn_ = true;
      return;
    }
  }
}

Shape& World::addEntity(std::unique_ptr<Shape> shape, double mass, const Material& material,
                        const btVector3& centre, double yawDegrees) {
  btTransform pose(yawRotation(yawDegrees), centre);
  shape->createBody(mass, material, pose);
  btRigidBody* body = shape->body();
  body->setUserIndex(static_cast<int>(entities_.size()));
  body->setUserPointer(const_cast<Material*>(&shape->material()));
  // Bullet's own thresholds (0.8 m/s, 1 rad/s) would freeze a ball still
  // rolling at half a metre a second; a body sleeps only once it has been
  // at rest, as observe() judges rest, for gDeactivationTime.
  body->setSleepingThresholds(kRestSpeed, kRestSpin);
  // Continuous collision detection, set from the body's size: a body that
  // moves more than its smallest half extent in one step could pass
  // through something thinner than itself between two steps, so Bullet
  // then sweeps a sphere of that radius along the step's motion and stops
  // the body where that sphere first touches. The sphere is half as big,
  // so it stays clear of what the body rests on (touching, a sweep along
  // the surface would report a hit at once). Slower bodies cost nothing.
  const btVector3 half = shape->halfExtents();
  const double inner = std::min({half.x(), half.y(), half.z()});
  body->setCcdMotionThreshold(inner);
  body->setCcdSweptSphereRadius(0.5 * inner);
  Tracker tracker;
  tracker.inner = inner;
  tracker.turningReach = shape->turningReach();
  body->setFlags((body->getFlags() & ~kGyroscopicFlags) | gyroscopicFlag(settings_.gyroscopic));
  if (!settings_.sleeping) body->setActivationState(DISABLE_DEACTIVATION);
  world_->addRigidBody(body);
  indexOf_.emplace(shape->name(), entities_.size());
  entities_.push_back(std::move(shape));
  trackers_.push_back(tracker);
  if (entities_.back()->material().friction > entityFriction_) {
    entityFriction_ = entities_.back()->material().friction;
    updateSmoothAcceleration();
  }
  return *entities_.back();
}

void World::makeKinematic(std::size_t i) {
  btRigidBody* body = entities_.at(i)->body();
  // Flags and mass change the body's broadphase group and solver role, so
  // it leaves the world while they change.
  world_->removeRigidBody(body);
  body->setMassProps(0.0, btVector3(0, 0, 0));
  body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  body->setLinearVelocity(btVector3(0, 0, 0));
  body->setAngularVelocity(btVector3(0, 0, 0));
  world_->addRigidBody(body);
  body->setActivationState(DISABLE_DEACTIVATION);
}

void World::placeKinematic(std::size_t i, const btVector3& centre, double yawDegrees) {
  btRigidBody* body = entities_.at(i)->body();
  body->setWorldTransform(btTransform(yawRotation(yawDegrees), centre));
}

void World::makeDynamic(std::size_t i, const btVector3& velocity) {
  Shape& shape = *entities_.at(i);
  btRigidBody* body = shape.body();
  world_->removeRigidBody(body);
  body->setCollisionFlags(body->getCollisionFlags() & ~btCollisionObject::CF_KINEMATIC_OBJECT);
  body->setMassProps(shape.mass(), shape.localInertia(shape.mass()));
  body->updateInertiaTensor();
  body->setInterpolationWorldTransform(body->getWorldTransform());
  world_->addRigidBody(body);
  if (!settings_.sleeping) body->setActivationState(DISABLE_DEACTIVATION);
  body->setLinearVelocity(velocity);
  body->setAngularVelocity(btVector3(0, 0, 0));
  body->activate(true);
  trackers_[i].atRest = false;
  trackers_[i].quietSince = -1.0;
}

// The largest acceleration gravity and sliding friction can give a body:
// g (1 + mu) with mu the largest friction any two of the scene's bodies
// combine to, and a margin of half as much again for the solver's
// rounding. A velocity change beyond it in one step is an impact.
// entityFriction_ is the largest of the entities', kept as they are added
// so that adding N entities costs O(N), not O(N^2).
void World::updateSmoothAcceleration() {
  const double otherFriction =
      std::max({entityFriction_, table_.spec().material.friction, ground_.material().friction});
  const double mu = combine(Material{entityFriction_}, Material{otherFriction}).friction;
  world_->setSmoothAcceleration(1.5 * settings_.gravity * (1.0 + mu));
}

Shape* World::find(std::string_view name) {
  const auto it = indexOf_.find(std::string(name));
  return it == indexOf_.end() ? nullptr : entities_[it->second].get();
}

Shape& World::entity(const std::string& name) {
  Shape* s = find(name);
  if (!s) throw std::invalid_argument("no entity named '" + name + "'");
  return *s;
}

std::string World::participantName(const btCollisionObject* object) const {
  return participantName(object->getUserIndex());
}

std::string World::participantName(int i) const {
  if (i == kTableIndex) return "table";
  if (i == kGroundIndex) return "ground";
  return entities_.at(static_cast<std::size_t>(i))->name();
}

std::vector<std::pair<std::string, std::string>> World::overlaps(double tolerance) {
  addLegsIfReachable();
  world_->performDiscreteCollisionDetection();
  std::vector<std::pair<std::string, std::string>> found;
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      if (manifold->getContactPoint(p).getDistance() < -tolerance) {
        found.emplace_back(participantName(manifold->getBody0()),
                           participantName(manifold->getBody1()));
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

std::vector<Vec3> World::contactPoints() const {
  // A point counts while it is within Bullet's contact breaking threshold
  // of touching; the point drawn is midway between the two surfaces.
  constexpr double kTouching = 1e-3;  // metres
  std::vector<Vec3> points;
  for (int m = 0; m < dispatcher_->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() > kTouching) continue;
      const btVector3 mid = 0.5 * (point.getPositionWorldOnA() + point.getPositionWorldOnB());
      points.push_back({mid.x(), mid.y(), mid.z()});
    }
  }
  return points;
}

double World::pushImpulse(const Arrow& arrow, const PushMagnitude& magnitude) {
  Shape& shape = entity(arrow.entity);
  if (magnitude.kind == PushMagnitude::Kind::Impulse) return magnitude.value;
  const Material contact = combine(shape.material(), table_.spec().material);
  return shape.mass() *
         stepLaunchSpeed(shape, magnitude.value, contact, settings_.gravity, settings_.timestep,
                         settings_.integrator);
}

// Report 3.5: a cube is pushed at the centre of a face, perpendicular to it;
// a sphere through its centre. Both lines of action pass through the centre
// of mass, so the push is a central impulse (arm x impulse is zero for
// parallel vectors; computing it would only add rounding).
void World::push(const Arrow& arrow, const PushMagnitude& magnitude) {
  start();
  Shape& shape = entity(arrow.entity);
  const double impulse = pushImpulse(arrow, magnitude);
  const double angle = arrow.worldAngleDegrees(shape.hasFaces() ? shape.yawDegrees() : 0.0);
  const btVector3 direction = toBullet(pushDirection(angle));

  btRigidBody* body = shape.body();
  body->activate(true);
  body->applyCentralImpulse(direction * impulse);

  const auto i = static_cast<std::size_t>(body->getUserIndex());
  trackers_[i].atRest = false;
  trackers_[i].quietSince = -1.0;

  Event e;
  e.t = time_;
  e.type = EventType::Push;
  e.entity = shape.name();
  if (arrow.face) e.direction = std::string(toString(*arrow.face));
  e.angle = angle;
  e.impulse = impulse;
  if (magnitude.kind == PushMagnitude::Kind::Step) e.step = magnitude.value;
  record(e);
}

// The report's "Entities on the table" rotation: a turn about the entity's
// own vertical axis through its centre.
void World::rotate(const std::string& name, double degrees) {
  start();
  Shape& shape = entity(name);
  btRigidBody* body = shape.body();
  btTransform pose = body->getWorldTransform();
  pose.setRotation(yawRotation(degrees) * pose.getRotation());
  body->setWorldTransform(pose);
  body->setInterpolationWorldTransform(pose);
  body->activate(true);

  Event e;
  e.t = time_;
  e.type = EventType::Rotate;
  e.entity = name;
  e.angle = degrees;
  record(e);
}

// Events are kept in time order; an at-rest event carries the earlier time
// its quiet window began.
void World::record(const Event& e) {
  auto at = std::upper_bound(events_.begin(), events_.end(), e.t,
                             [](double t, const Event& other) { return t < other.t; });
  events_.insert(at, e);
}

void World::start() {
  if (started_) return;
  started_ = true;
  world_->performDiscreteCollisionDetection();
  observe(false);
  // With sleeping on, what rests on a support at the start begins asleep,
  // as Bullet would put it after gDeactivationTime (2 s) at rest: it costs
  // nothing until a push or a moving body touching it wakes it (Bullet
  // wakes an island with any active body in it). Bodies in the air stay
  // awake.
  if (settings_.sleeping) {
    for (std::size_t i = 0; i < entities_.size(); ++i) {
      if (trackers_[i].support != kNoSupport) entities_[i]->body()->setActivationState(ISLAND_SLEEPING);
    }
  }
}

void World::step() {
  start();
  addLegsIfReachable();
  const int n = substeps();
  for (int k = 0; k < n; ++k) world_->step(settings_.timestep / n);
  ++steps_;
  time_ = static_cast<double>(steps_) * settings_.timestep;
  observe(true);
}

// How many equal parts a step is cut into: enough that no awake entity
// moves more than kSubstepTravel of its smallest half extent in one part,
// counting both its centre's travel and its farthest point's turn about
// the centre, and at most Settings::maxSubsteps. A body that moves more
// than that in one step strikes what it meets part-way into it, at a time
// of impact only a shorter step finds, and a body turning fast reaches the
// floor with corners the step's start did not find
// (docs/bullet-corrections.md). Slow scenes and bodies at rest are stepped
// whole.
int World::substeps() const {
  if (settings_.maxSubsteps <= 1) return 1;
  double parts = 1.0;
  for (std::size_t i = 0; i < entities_.size(); ++i) {
    const btRigidBody* body = entities_[i]->body();
    if (body->isStaticOrKinematicObject() || !body->isActive()) continue;
    const Tracker& t = trackers_[i];
    const double travel = (body->getLinearVelocity().length() + body->getAngularVelocity().length() * t.turningReach) *
                          settings_.timestep;
    const double need = travel / (kSubstepTravel * t.inner);
    if (!(need <= parts)) parts = need;  // keeps a NaN, which std::max would drop
  }
  // Written so that a non-finite speed (a diverging run, which the
  // divergence guard then stops) gives the cap, never a cast of NaN.
  return parts < settings_.maxSubsteps ? static_cast<int>(std::ceil(parts)) : settings_.maxSubsteps;
}

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
void World::observe(bool emit) {
  const std::size_t n = entities_.size();

  // Contacts, one entry per (entity, other body) pair and side: how close
  // they are, and how hard the other pushes the entity up. Entries are
  // merged by sorting, in a buffer kept from step to step.
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
  std::sort(contacts_.begin(), contacts_.end(), [](const Contact& x, const Contact& y) {
    return x.entity != y.entity ? x.entity < y.entity : x.other < y.other;
  });
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

  std::set<std::pair<int, int>> touching;
  for (const Contact& c : contacts_) {
    if (c.other < 0 || c.entity > c.other) continue;  // each entity pair once
    const auto pair = std::make_pair(c.entity, c.other);
    const bool was = touching_.count(pair) > 0;
    if (c.distance <= kTouchDistance || (was && c.distance <= kApartDistance)) {
      touching.insert(pair);
      if (emit && !was) {
        Event e;
        e.t = time_;
        e.type = EventType::ContactBegin;
        e.entity = entities_[pair.first]->name();
        e.other = entities_[pair.second]->name();
        record(e);
      }
    }
  }
  touching_ = std::move(touching);

  // Support: the body pushing each entity up hardest (ties: the lower
  // index, the table and ground first).
  std::vector<int> support(n, kNoSupport);
  std::vector<double> strongest(n, -1.0);
  for (const Contact& c : contacts_) {
    if (c.support > strongest[c.entity]) {
      strongest[c.entity] = c.support;
      support[c.entity] = c.other;
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    Shape& shape = *entities_[i];
    Tracker& tracker = trackers_[i];

    // A new support that is not the last one means the entity landed.
    if (support[i] != tracker.support) {
      tracker.support = support[i];
      shape.setSupport(support[i] == kNoSupport ? "none" : participantName(support[i]));
      if (support[i] != kNoSupport) {
        if (emit && support[i] != tracker.lastSupport) {
          Event e;
          e.t = time_;
          e.type = EventType::Lands;
          e.entity = shape.name();
          e.on = shape.support();
          record(e);
        }
        tracker.lastSupport = support[i];
      }
    }

    // Report 3.4: the centre passing an edge starts the drop.
    if (shape.checkBoundary(table_) && emit) {
      Event e;
      e.t = time_;
      e.type = EventType::LeavesTable;
      e.entity = shape.name();
      e.edge = std::string(edgeName(shape.status()));
      record(e);
    }

    // Rest: slow for a whole window; the event carries the window's start.
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

    // The drop ends once the entity is at rest below the table top.
    if (isDropping(shape.status()) && tracker.atRest &&
        shape.position().y() < table_.topHeight()) {
      shape.finishDrop();
    }
  }
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
