#include "measure/PlainBullet.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "core/DirectionDef.h"
#include "physics/shapes/Shape.h"
#include "physics/World.h"
#include "sim/SceneBuilder.h"

namespace tabletop {
namespace {

// A push as Bullet applies it: an impulse on one body at a time.
struct Kick {
  double at;        // s
  std::size_t body;
  btVector3 impulse;  // N s
};

btRigidBody::btRigidBodyConstructionInfo staticInfo(btCollisionShape* shape, const btVector3& at,
                                                    const Material& m) {
  btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape);
  info.m_startWorldTransform.setIdentity();
  info.m_startWorldTransform.setOrigin(at);
  info.m_friction = m.friction;
  info.m_restitution = m.restitution;
  return info;
}

// The deepest contact among the world's manifolds, m (0 if none).
double deepestContact(btCollisionDispatcher& dispatcher) {
  double deepest = 0.0;
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int k = 0; k < manifold->getNumContacts(); ++k) {
      deepest = std::max(deepest, -static_cast<double>(manifold->getContactPoint(k).getDistance()));
    }
  }
  return deepest;
}

// One run; the worst drift (and the settled window, with `settled`) is
// watched when `worstDrift` is given (the timed runs leave it out).
double oneRun(const Scenario& scenario, World& start, const std::vector<Kick>& kicks, double timestep,
              double duration, std::vector<Vec3>& centres, double* worstDrift = nullptr,
              SettledWatch* settled = nullptr) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
  world.setGravity(btVector3(0, -scenario.settings.gravity, 0));

  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  const TableSpec& t = scenario.table;
  shapes.push_back(std::make_unique<btBoxShape>(btVector3(t.width / 2, t.thickness / 2, t.depth / 2)));
  bodies.push_back(std::make_unique<btRigidBody>(staticInfo(
      shapes.back().get(), btVector3(t.centreX, t.height - t.thickness / 2, t.centreZ), t.material)));
  const double legHeight = t.height - t.thickness;
  for (int i = 0; i < 4; ++i) {
    shapes.push_back(std::make_unique<btCylinderShape>(btVector3(t.legRadius, legHeight / 2, t.legRadius)));
    const Vec3 c = t.legCentre(i);
    bodies.push_back(std::make_unique<btRigidBody>(
        staticInfo(shapes.back().get(), btVector3(c.x, legHeight / 2, c.z), t.material)));
  }
  shapes.push_back(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0));
  bodies.push_back(std::make_unique<btRigidBody>(staticInfo(shapes.back().get(), btVector3(0, 0, 0), scenario.ground)));
  for (auto& b : bodies) world.addRigidBody(b.get());

  // The entities, each with a shape of its own made as tabletop makes it.
  std::vector<std::unique_ptr<Shape>> entityShapes;
  std::vector<btRigidBody*> entities;
  for (std::size_t i = 0; i < scenario.entities.size(); ++i) {
    const Shape& from = *start.entities()[i];
    entityShapes.push_back(makeShape(scenario.entities[i]));
    btCollisionShape* shape = &entityShapes.back()->collisionShape();
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(from.mass(), inertia);
    btRigidBody::btRigidBodyConstructionInfo info(from.mass(), nullptr, shape, inertia);
    info.m_startWorldTransform = from.body()->getWorldTransform();
    info.m_friction = from.material().friction;
    info.m_restitution = from.material().restitution;
    info.m_rollingFriction = from.material().rollingFriction;
    info.m_spinningFriction = from.material().spinningFriction;
    bodies.push_back(std::make_unique<btRigidBody>(info));
    btRigidBody* body = bodies.back().get();
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setLinearVelocity(from.body()->getLinearVelocity());
    body->setAngularVelocity(from.body()->getAngularVelocity());
    world.addRigidBody(body);
    entities.push_back(body);
  }

  const auto began = std::chrono::steady_clock::now();
  std::size_t next = 0;
  const long steps = std::lround(duration / timestep);
  for (long s = 0; s < steps; ++s) {
    for (; next < kicks.size() && kicks[next].at <= s * timestep + 1e-12; ++next) {
      entities[kicks[next].body]->applyCentralImpulse(kicks[next].impulse);
    }
    world.stepSimulation(timestep, 0, timestep);
    if (worstDrift == nullptr) continue;
    if (settled != nullptr) {
      settled->observe((s + 1) * timestep, std::vector<const btRigidBody*>(entities.begin(), entities.end()),
                       deepestContact(dispatcher));
    }
    for (std::size_t i = 0; i < entities.size(); ++i) {
      const btVector3 moved =
          entities[i]->getWorldTransform().getOrigin() - start.entities()[i]->body()->getWorldTransform().getOrigin();
      *worstDrift = std::max(*worstDrift, static_cast<double>(moved.length()));
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  centres.clear();
  for (const btRigidBody* body : entities) {
    const btVector3& c = body->getWorldTransform().getOrigin();
    centres.push_back({c.x(), c.y(), c.z()});
  }
  for (auto& b : bodies) world.removeRigidBody(b.get());
  return wall;
}

}  // namespace

PlainRun runPlainBullet(const Scenario& scenario, double timestep, double duration, int repeats,
                        double settledFrom) {
  // tabletop's World places the entities (seated on what they stand on)
  // and turns each push into its impulse; its own steps are not taken.
  Settings settings = scenario.settings;
  settings.timestep = timestep;
  std::unique_ptr<World> start = buildWorld(scenario, settings);
  std::vector<Kick> kicks;
  for (const Action& a : scenario.script) {
    if (a.type != Action::Type::Push) continue;
    Shape* shape = start->find(a.arrow.entity);
    if (shape == nullptr) continue;
    const double angle = a.arrow.worldAngleDegrees(shape->hasFaces() ? shape->yawDegrees() : 0.0);
    const Vec3 d = pushDirection(angle);
    const double impulse = start->pushImpulse(a.arrow, a.magnitude);
    std::size_t body = 0;
    for (; body < start->entities().size() && start->entities()[body].get() != shape; ++body) {
    }
    kicks.push_back({a.at.value_or(0.0), body, btVector3(d.x, d.y, d.z) * impulse});
  }
  std::stable_sort(kicks.begin(), kicks.end(), [](const Kick& a, const Kick& b) { return a.at < b.at; });
  PlainRun run;
  run.simulated = duration;
  SettledWatch watch(settledFrom, duration, scenario.settings.gravity);
  oneRun(scenario, *start, kicks, timestep, duration, run.centres, &run.worstDrift,
         settledFrom >= 0 ? &watch : nullptr);  // warm-up
  run.settled = watch.result();
  std::vector<double> walls;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    walls.push_back(oneRun(scenario, *start, kicks, timestep, duration, run.centres));
  }
  std::nth_element(walls.begin(), walls.begin() + static_cast<long>(walls.size() / 2), walls.end());
  run.costMsPerSecond = walls[walls.size() / 2] / duration * 1000.0;
  return run;
}

}  // namespace tabletop
