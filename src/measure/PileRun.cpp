#include "measure/PileRun.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/StateHash.h"
#include "measure/PlainBullet.h"
#include "physics/World.h"
#include "scenes/Pile.h"
#include "sim/DivergenceGuard.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {
namespace {

// tabletop's run of one pile as `run` makes it (with the divergence
// guard), watched after every step, stopped at the budget.
PileSide runTabletop(const Scenario& pile, double budgetSeconds) {
  std::unique_ptr<World> world = buildWorld(pile, pile.settings);
  ScriptPlayer player(pile, pile.settings, *world, {});
  SettledWatch watch(Pile::kSettle, pile.settings.duration, pile.settings.gravity);
  std::vector<const btRigidBody*> bodies;
  for (const auto& e : world->entities()) bodies.push_back(e->body());
  PileSide side;
  double wall = 0.0;
  try {
    player.runDue();
    while (!player.finished()) {
      if (wall > budgetSeconds) {
        std::ostringstream note;
        note << "stopped at the " << budgetSeconds << " s budget";
        side.note = note.str();
        break;
      }
      const auto before = std::chrono::steady_clock::now();
      player.step();
      wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
      watch.observe(world->time(), bodies, world->deepestPenetration());
    }
  } catch (const DivergenceError& e) {
    side.note = std::string("diverged: ") + e.what();
  }
  side.simulated = world->time();
  const double steps = std::round(side.simulated / pile.settings.timestep);
  if (steps > 0) side.partsPerStep = static_cast<double>(world->solverUse().parts) / steps;
  side.largestIsland = world->solverUse().largestIsland;
  side.costMsPerSecond = side.simulated > 0 ? 1e3 * wall / side.simulated : 0.0;
  side.settled = watch.result();
  side.hash = stateHash(world->snapshot());
  return side;
}

}  // namespace

std::vector<PilePoint> measurePiles(const std::vector<int>& sizes, double budgetSeconds, int threads,
                                    const MeasureHooks& hooks) {
  std::vector<PilePoint> points;
  hooks.start(static_cast<long>(sizes.size()));
  for (int n : sizes) {
    if (hooks.stop()) break;
    Scenario pile = Pile::make(n);
    PilePoint p;
    p.bodies = n;
    p.tabletop = runTabletop(pile, budgetSeconds);
    if (threads > 1 && p.tabletop.note.empty()) {
      pile.settings.threads = threads;
      p.threads = threads;
      p.threaded = runTabletop(pile, budgetSeconds);
    }
    const PlainRun bullet = runPlainBullet(pile, pile.settings.timestep, pile.settings.duration, 1, Pile::kSettle);
    p.bullet.costMsPerSecond = bullet.costMsPerSecond;
    p.bullet.simulated = bullet.simulated;
    p.bullet.settled = bullet.settled;
    points.push_back(p);
    hooks.advance(pile.name);
    if (!p.tabletop.note.empty()) break;
  }
  return points;
}

std::map<std::string, double> pileExponents(const std::vector<PilePoint>& points) {
  std::vector<double> n, tabletop, bullet;
  for (const PilePoint& p : points) {
    n.push_back(p.bodies);
    tabletop.push_back(p.tabletop.costMsPerSecond);
    bullet.push_back(p.bullet.costMsPerSecond);
  }
  if (n.size() < 2) return {};
  return {{"tabletop", growthExponent(n, tabletop)}, {"bullet", growthExponent(n, bullet)}};
}

}  // namespace tabletop
