#include "physics/World.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/Angle.h"
#include "physics/contact/ContactMaterial.h"
#include "physics/collision/Reach.h"
#include "physics/StepPush.h"
#include "physics/step/FreeFlight.h"

namespace tabletop {
namespace {

// Body user indices: entities use their index; these mark the rest.
constexpr int kTableIndex = -2;
constexpr int kGroundIndex = -3;

// The gravity, m/s^2, below which a scene's smooth accelerations are
// taken as at this one (updateSmoothAcceleration).
constexpr double kLeastGravity = 0.01;

// How far an entity may move in one part of a step, as a share of its
// smallest half extent (World::substeps).
constexpr double kSubstepTravel = 0.5;
// How far an entity's turn may move its surface in a step, as a share of
// its smallest half extent, for it to slide on what carries it: a body
// that rocks or tumbles there is cut into parts as before.
constexpr double kSlideTurn = 0.05;

btQuaternion yawRotation(double degrees) {
  return btQuaternion(btVector3(0, 1, 0), convertAngle(degrees));
}

// Bullet's rigid-body flag for the gyroscopic term (Settings::gyroscopic).
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
      table_(table, settings.bullet.legsWhenReachable),
      ground_(ground, settings.bullet.floorPairsNearFloor) {
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
  return addEntity(std::move(shape), mass, material, centre, yawRotation(yawDegrees));
}

Shape& World::addEntity(std::unique_ptr<Shape> shape, double mass, const Material& material,
                        const btVector3& centre, const btQuaternion& orientation) {
  btTransform pose(orientation, centre);
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
  body->setFlags((body->getFlags() & ~kGyroscopicFlags) | gyroscopicFlag(settings_.bullet.gyroscopic));
  if (!settings_.bullet.sleeping) body->setActivationState(DISABLE_DEACTIVATION);
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
  if (!settings_.bullet.sleeping) body->setActivationState(DISABLE_DEACTIVATION);
  body->setLinearVelocity(velocity);
  body->setAngularVelocity(btVector3(0, 0, 0));
  body->activate(true);
  trackers_[i].atRest = false;
  trackers_[i].quietSince = -1.0;
}

// The largest acceleration gravity and sliding friction can give a body:
// g (1 + mu) with mu the largest friction any two of the scene's bodies
// combine to, and a margin of half as much again for the solver's
// rounding. A velocity change beyond it in one step is an impact. Without
// gravity nothing is smooth, but the threshold must not be 0, which turns
// the impact handling off (every impact of a weightless scene was
// inelastic): it is taken as at kLeastGravity.
// entityFriction_ is the largest of the entities', kept as they are added
// so that adding N entities costs O(N), not O(N^2).
void World::updateSmoothAcceleration() {
  const double otherFriction =
      std::max({entityFriction_, table_.spec().material.friction, ground_.material().friction});
  const double mu = combine(Material{entityFriction_}, Material{otherFriction}).friction;
  world_->setSmoothAcceleration(1.5 * std::max(settings_.gravity, kLeastGravity) * (1.0 + mu));
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

Support World::participant(const btCollisionObject* object) const {
  return participant(object->getUserIndex());
}

Support World::participant(int i) const {
  if (i == kTableIndex) return Support::table();
  if (i == kGroundIndex) return Support::ground();
  return Support::entity(entities_.at(static_cast<std::size_t>(i))->name());
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
  if (settings_.bullet.sleeping) {
    for (std::size_t i = 0; i < entities_.size(); ++i) {
      if (trackers_[i].support != kNoSupport) entities_[i]->body()->setActivationState(ISLAND_SLEEPING);
    }
  }
}

void World::step() {
  start();
  addLegsIfReachable();
  // Where each entity starts the step, so that an edge passed inside it is
  // placed at its own time (observe()).
  for (std::size_t i = 0; i < entities_.size(); ++i) {
    trackers_[i].lastCentre = entities_[i]->position();
    trackers_[i].lastVelocity = entities_[i]->body()->getLinearVelocity();
  }
  int n = substeps();
  // An island that carried a load too large to pivot in the last step is
  // swept long, and in parts no longer than those sweeps hold it in.
  if (pipeline_.solver->takeLongSweeps() && settings_.maxSubsteps > 1) {
    const int loaded = static_cast<int>(std::ceil(settings_.timestep / IslandSolver::kLongSweepStep - 1e-9));
    n = std::min(std::max(n, loaded), settings_.maxSubsteps);
  }
  struck_.clear();
  if (!loads_.empty()) takeLoads();
  for (int k = 0; k < n; ++k) {
    world_->step(settings_.timestep / n);
    for (DynamicsWorld::Struck pair : world_->struck()) {
      pair.at += k * settings_.timestep / n;
      struck_.push_back(pair);
    }
  }
  if (!loads_.empty()) {
    loads_.clear();
    world_->setLoads({});
    updateSmoothAcceleration();
  }
  ++steps_;
  time_ = clock_.time(steps_, settings_.timestep);
  observe(true);
}


// How many equal parts a step is cut into: enough that no awake entity
// moves more than kSubstepTravel of its smallest half extent in one part,
// counting both its centre's travel and its farthest point's turn about
// the centre, and at most Settings::maxSubsteps. A body that moves more
// than that in one step strikes what it meets part-way into it, at a time
// of impact only a shorter step finds, and a body turning fast reaches the
// floor with corners the step's start did not find
// (docs/bullet-corrections.md). Slow scenes, bodies at rest, and fast
// bodies that nothing but what they slide on is near are stepped whole
// (docs/hard-cases.md).
int World::substeps() const {
  if (settings_.maxSubsteps <= 1) return 1;
  double parts = 1.0;
  const double gravity = world_->getGravity().length();
  for (std::size_t i = 0; i < entities_.size(); ++i) {
    const btRigidBody* body = entities_[i]->body();
    if (body->isStaticOrKinematicObject() || !body->isActive()) continue;
    const Tracker& t = trackers_[i];
    const double turn = body->getAngularVelocity().length() * t.turningReach * settings_.timestep;
    const double travel = body->getLinearVelocity().length() * settings_.timestep + turn;
    const double need = travel / (kSubstepTravel * t.inner);
    if (need <= parts) continue;
    // A body nothing is near strikes nothing in the step: it is stepped
    // whole, however fast (a ball in flight). Near is within what it can
    // move in the step, gravity's share included, and the distance ahead
    // of touching at which contact points are made. What it slides on is
    // not near, unless it turns (its corners could come down into it).
    const double reach = travel + 0.5 * gravity * settings_.timestep * settings_.timestep + gContactBreakingThreshold;
    const double slideStep = turn <= kSlideTurn * t.inner ? settings_.timestep : 0.0;
    if (std::isfinite(need) && !nearAnything(*world_, *body, reach, slideStep)) continue;
    parts = need;  // a NaN too, which std::max would drop
  }
  // Written so that a non-finite speed (a diverging run, which the
  // divergence guard then stops) gives the cap, never a cast of NaN.
  return parts < settings_.maxSubsteps ? static_cast<int>(std::ceil(parts)) : settings_.maxSubsteps;
}

WorkCount World::work() const {
  WorkCount w = world_->work();
  w += pipeline_.solver->work();
  return w;
}

SolverUse World::solverUse() const {
  SolverUse use = pipeline_.solver->use();
  use.partBudget = pipeline_.world->partBudgetSteps();
  use.parts = pipeline_.world->parts();
  return use;
}

}  // namespace tabletop
