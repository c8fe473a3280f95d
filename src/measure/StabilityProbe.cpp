#include "measure/StabilityProbe.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "core/StateHash.h"
#include "measure/SettledWatch.h"
#include "physics/World.h"
#include "sim/SceneBuilder.h"

namespace tabletop {
namespace {

// Kinetic, rotational and potential energy of every entity, J.
double totalEnergy(const World& world, double gravity) {
  double e = 0.0;
  for (const auto& entity : world.entities()) e += mechanicalEnergy(*entity->body(), gravity);
  return e;
}

}  // namespace

StabilityReport probeStability(const Scenario& scenario, const Settings& settings, const StepObserver& afterStep) {
  std::unique_ptr<World> world = buildWorld(scenario, settings);
  ScriptPlayer player(scenario, settings, *world, afterStep);
  StabilityReport r;

  std::vector<btVector3> start;
  for (const auto& e : world->entities()) start.push_back(e->position());
  const Table& table = world->table();
  const double restWindow = std::min(1.0, 0.5 * settings.duration);

  const auto watch = [&]() {
    for (std::size_t i = 0; i < start.size(); ++i) {
      const btRigidBody& body = *world->entities()[i]->body();
      const btVector3 centre = body.getCenterOfMassPosition();
      r.worstDrift = std::max(r.worstDrift, double((centre - start[i]).length()));
      r.farthest = std::max(r.farthest, std::hypot(centre.x() - table.spec().centreX, centre.z() - table.spec().centreZ));
      const double low = -world->entities()[i]->reach(btVector3(0, -1, 0));
      r.lowestOverFloor = std::min(r.lowestOverFloor, low);
      // Over the top: the report's drop test (3.4) still says OnTable.
      if (table.statusAt(centre.x(), centre.z()) == EntityPositionStatus::OnTable) {
        r.lowestOverTop = std::min(r.lowestOverTop, low - table.topHeight());
      }
      if (world->time() > settings.duration - restWindow) {
        r.restSpeed = std::max(r.restSpeed, double(body.getLinearVelocity().length()));
      }
    }
    r.worstPenetration = std::max(r.worstPenetration, world->deepestPenetration());
  };

  double lowest = 0.0;  // the lowest energy since the last push
  double given = 0.0;   // the energy just after the last push
  int pushes = -1;
  try {
    player.runDue();
    while (true) {
      const double e = totalEnergy(*world, settings.gravity);
      r.energyScale = std::max(r.energyScale, std::abs(e));
      if (player.pushes() != pushes) {
        pushes = player.pushes();
        lowest = e;
        given = e;
      } else {
        r.energyGain = std::max(r.energyGain, e - lowest);
        r.energyExcess = std::max(r.energyExcess, e - given);
        lowest = std::min(lowest, e);
      }
      if (player.finished()) break;
      const auto before = std::chrono::steady_clock::now();
      player.step();
      r.wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
      watch();
    }
  } catch (const DivergenceError& e) {
    r.complete = false;
    r.failure = e.what();
  }
  r.steps = world->steps();
  r.simulated = world->time();
  r.stateHash = stateHash(world->snapshot());
  r.solverUse = world->solverUse();
  return r;
}

}  // namespace tabletop
