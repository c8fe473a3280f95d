#pragma once

#include <memory>

#include <btBulletDynamicsCommon.h>

#include "core/Settings.h"
#include "core/TableSpec.h"
#include "physics/step/DynamicsWorld.h"
#include "physics/solver/IslandSolver.h"

namespace tabletop {

/// Bullet's pipeline for one scene, built and configured from the settings:
/// the collision configuration, the dispatcher (ContactDispatcher), the
/// broadphase, the contact solver (IslandSolver)
/// and the dynamics world (DynamicsWorld), with the choices that make
/// contacts right and runs deterministic (see Pipeline.cpp). A World owns
/// one; it holds no bodies of its own.
struct Pipeline {
  Pipeline(const Settings& settings, const TableSpec& table);
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  std::unique_ptr<btDefaultCollisionConfiguration> configuration;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btBroadphaseInterface> broadphase;
  std::unique_ptr<IslandSolver> solver;
  std::unique_ptr<DynamicsWorld> world;
};

}  // namespace tabletop
