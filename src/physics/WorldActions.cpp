#include "physics/World.h"

#include <cmath>

#include "core/Angle.h"
#include "physics/StepPush.h"
#include "physics/contact/ContactMaterial.h"

// What acts on the scene from outside, between its steps: the report's
// push (report 3.5), impulses and loads given as vectors, and a new
// timestep or gravity. The step itself is in World.cpp.
namespace tabletop {

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
// parallel vectors; computing it would only add rounding). A push `at` a
// point of the body acts there, and sets it spinning.
void World::push(const Arrow& arrow, const PushMagnitude& magnitude) {
  start();
  Shape& shape = entity(arrow.entity);
  const double impulse = pushImpulse(arrow, magnitude);
  const double angle = arrow.worldAngleDegrees(shape.hasFaces() ? shape.yawDegrees() : 0.0);
  const btVector3 direction = toBullet(pushDirection(angle));

  btRigidBody* body = shape.body();
  if (arrow.at) {
    const btVector3 arm = body->getWorldTransform().getBasis() * toBullet(*arrow.at);
    body->applyImpulse(direction * impulse, arm + shape.position() - body->getCenterOfMassPosition());
  } else {
    body->applyCentralImpulse(direction * impulse);
  }

  Event e;
  e.type = EventType::Push;
  e.face = arrow.face;
  e.angle = angle;
  e.impulse = impulse;
  if (magnitude.kind == PushMagnitude::Kind::Step) e.step = magnitude.value;
  recordPush(shape, e);
}

// An impulse J at a point r from the centre of mass changes the velocity
// by J / m and the spin by I^-1 (r x J) (Bullet's applyImpulse).
void World::applyImpulse(const std::string& name, const Vec3& impulse, const std::optional<Vec3>& point) {
  start();
  Shape& shape = entity(name);
  btRigidBody* body = shape.body();
  if (point) {
    body->applyImpulse(toBullet(impulse), toBullet(*point) - body->getCenterOfMassPosition());
  } else {
    body->applyCentralImpulse(toBullet(impulse));
  }
  Event e;
  e.type = EventType::Push;
  e.angle = toDegrees(std::atan2(-impulse.z, impulse.x));
  e.impulse = impulse.length();
  recordPush(shape, e);
}

void World::recordPush(Shape& shape, Event e) {
  btRigidBody* body = shape.body();
  body->activate(true);
  const auto i = static_cast<std::size_t>(body->getUserIndex());
  trackers_[i].atRest = false;
  trackers_[i].quietSince = -1.0;
  e.t = time_;
  e.entity = shape.name();
  record(e);
}

void World::takeLoads() {
  double most = 0.0;  // m/s^2
  for (const DynamicsWorld::Load& load : loads_) {
    const Tracker& t = trackers_.at(static_cast<std::size_t>(load.body->getUserIndex()));
    const btVector3 spinUp = load.body->getInvInertiaTensorWorld() * load.torque;
    most = std::max(most, double(load.force.length() * load.body->getInvMass() + spinUp.length() * t.turningReach));
  }
  world_->setSmoothAcceleration(world_->smoothAcceleration() + most);
  world_->setLoads(loads_);
}

// The bound on smooth accelerations takes in each load's linear and
// turning acceleration, so that the step reads the velocity it changes as
// smooth, not as an impact.
void World::applyForce(const std::string& name, const Vec3& force, const Vec3& torque,
                       const std::optional<Vec3>& point) {
  start();
  Shape& shape = entity(name);
  btRigidBody* body = shape.body();
  btVector3 moment = toBullet(torque);
  if (point) moment += (toBullet(*point) - body->getCenterOfMassPosition()).cross(toBullet(force));
  body->activate(true);
  loads_.push_back({body, toBullet(force), moment});
}

void World::setTimestep(double seconds) {
  clock_.changeAt(steps_, time_);
  settings_.timestep = seconds;
}

// Bullet gives every body the world's gravity; the solver's slip test and
// the step's bound on smooth accelerations are made from it too. Sleeping
// bodies wake, as under any change to what acts on them.
void World::setGravity(double g) {
  settings_.gravity = g;
  world_->changeGravity(g);
  pipeline_.solver->setGravity(g);
  updateSmoothAcceleration();
  for (const auto& e : entities_) e->body()->activate(true);
}

}  // namespace tabletop
