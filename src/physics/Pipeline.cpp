#include "physics/Pipeline.h"

#include <algorithm>

#include "physics/collision/ContactDispatcher.h"
#include "physics/collision/SolidOnFaceAlgorithm.h"
#include "physics/solver/IslandSolver.h"
#include "physics/collision/SolidOnPlaneAlgorithm.h"

namespace tabletop {
namespace {

// Room the sweep-and-prune broadphase makes: bodies beyond it are still
// paired correctly, only less finely.
constexpr int kSweepHandles = 1 << 16;

std::unique_ptr<btBroadphaseInterface> makeBroadphase(Broadphase kind, const TableSpec& table) {
  switch (kind) {
    case Broadphase::Dbvt: break;
    case Broadphase::SweepAndPrune: {
      // Quantised over the table and well around it: the space the bodies
      // of a scene move in.
      const double reach = 10.0 + std::max(table.width, table.depth);
      const btVector3 low(table.centreX - reach, -reach, table.centreZ - reach);
      const btVector3 high(table.centreX + reach, table.height + reach, table.centreZ + reach);
      return std::make_unique<bt32BitAxisSweep3>(low, high, kSweepHandles);
    }
    case Broadphase::Simple: return std::make_unique<btSimpleBroadphase>(kSweepHandles);
  }
  return std::make_unique<btDbvtBroadphase>();
}

// Manifolds and collision algorithms the configuration's pools hold; past
// that Bullet takes them from the heap. Its defaults (4096 each) made and
// zeroed 4.5 MB for every world: 15% of a sweep of example 2's short runs,
// and under an allocator that hands large blocks back to the system at
// once (a Dask worker's) every run paid for the pages afresh.
constexpr int kPooled = 64;

// The configuration, its pool of collision algorithms sized for tabletop's
// own too: Bullet sizes the pool's elements for its algorithms alone, and
// an algorithm larger than that writes past its element into the next.
std::unique_ptr<btDefaultCollisionConfiguration> makeConfiguration() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = kPooled;
  info.m_defaultMaxCollisionAlgorithmPoolSize = kPooled;
  info.m_customCollisionAlgorithmMaxElementSize =
      static_cast<int>(std::max(sizeof(SolidOnFaceAlgorithm), sizeof(SolidOnPlaneAlgorithm)));
  return std::make_unique<btDefaultCollisionConfiguration>(info);
}

}  // namespace

Pipeline::Pipeline(const Settings& settings, const TableSpec& table)
    : configuration(makeConfiguration()),
      dispatcher(std::make_unique<ContactDispatcher>(configuration.get())),
      broadphase(makeBroadphase(settings.bullet.broadphase, table)),
      solver(std::make_unique<IslandSolver>(settings.solver, kDirectRowLimit, settings.gravity)),
      world(std::make_unique<DynamicsWorld>(dispatcher.get(), broadphase.get(), solver.get(), configuration.get())) {
  // A box resting on the ground plane gets all its corner contacts in the
  // first step, not one more per step (which let it sink for a step).
  configuration->setPlaneConvexMultipointIterations();
  world->setGravity(btVector3(0, -settings.gravity, 0));
  // Bullet recomputes every object's bounding box every step, the table's
  // compound and the floor included, though nothing static ever moves
  // (a tenth of a ball's step in flight). Only bodies that can move are
  // updated: Bullet puts static bodies to sleep as they are added, and a
  // body asleep (with `sleeping` on) is still until something wakes it.
  world->setForceUpdateAllAabbs(false);
  world->setSecondOrderPositions(settings.integrator == Integrator::Trapezoid);
  world->setThreads(settings.threads);
  btContactSolverInfo& info = world->getSolverInfo();
  info.m_numIterations = settings.iterations;
  // One island at a time, so each is solved its own way and the row limit
  // applies to it (IslandSolver).
  info.m_minimumSolverBatchSize = 1;
  // Split impulse for every penetration, not only those deeper than 4 cm:
  // pushing bodies apart then never leaves velocity behind, so a body
  // resting on the table does not bounce off it at the first step.
  info.m_splitImpulse = 1;
  info.m_splitImpulsePenetrationThreshold = 0;
  // Full warm starting (Settings::warmStart): measured on a stack of ten
  // 0.1 m cubes at 240 Hz and 10 iterations, Bullet's 0.85 let the stack
  // lose 15% of its support each step and fall after 1.6 s; with 1 it
  // stands (5.5 mm worst drift over 60 s, all of it in the first second).
  info.m_warmstartingFactor = settings.bullet.warmStart;
  // Bullet sums the squared velocity change of every row over a sweep.
  info.m_leastSquaresResidualThreshold = settings.bullet.solverTolerance * settings.bullet.solverTolerance;
  // Sorted pairs make the solver's order independent of memory layout.
  world->getDispatchInfo().m_deterministicOverlappingPairs = true;
  // Separating axes by SAT, not GJK: for a cube centred over the table
  // top GJK's closest points are degenerate, and the clipped face came out
  // with a point at the centre instead of the four corners (a 0.2 m step
  // then ended 2.8 mm short and turned 2 degrees).
  world->getDispatchInfo().m_enableSatConvex = true;
}

}  // namespace tabletop
