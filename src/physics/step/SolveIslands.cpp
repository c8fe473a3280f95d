#include "physics/step/DynamicsWorld.h"

#include <mutex>

#include "physics/solver/IslandSolver.h"

// Stage 6's islands on every thread (docs/step.md, "Threads"). Islands
// share no moving body, so each is solved from its own bodies and points
// alone, and writes only to them: solved in any order, on any thread, by
// any of the IslandSolvers that follow the same settings, each ends to the
// bit as it ends solved alone. What the solvers count is summed after.
namespace tabletop {
namespace {

// Below this many manifolds in all, a solve is not worth waking threads
// for (the result is the same either way).
constexpr int kSharedManifolds = 16;

// Bullet's profiler (BT_PROFILE in its solver) keeps a tree of timings
// per thread, and gives each thread its index from a counter that two
// threads starting at once may read alike. tabletop never reads it: it is
// switched off, once for the process, before a second thread solves.
void noProfileZone(const char*) {}
void noProfileLeave() {}
void switchOffBulletProfiler() {
  static std::once_flag once;
  std::call_once(once, [] {
    btSetCustomEnterProfileZoneFunc(noProfileZone);
    btSetCustomLeaveProfileZoneFunc(noProfileLeave);
  });
}

// Bullet's islands, handed to `take` in its order instead of solved.
template <typename Take>
class IslandList : public btSimulationIslandManager::IslandCallback {
 public:
  explicit IslandList(Take take) : take_(take) {}
  void processIsland(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
                     int) override {
    take_(bodies, numBodies, manifolds, numManifolds);
  }

 private:
  Take take_;
};

// Whether an island's points touch a kinematic body: Bullet's solver
// notes its own index in such a body, which islands share.
bool touchesKinematic(btPersistentManifold** manifolds, int numManifolds) {
  for (int m = 0; m < numManifolds; ++m) {
    if (manifolds[m]->getBody0()->isKinematicObject() || manifolds[m]->getBody1()->isKinematicObject()) return true;
  }
  return false;
}

}  // namespace

DynamicsWorld::~DynamicsWorld() = default;

void DynamicsWorld::setThreads(int threads) {
  helpers_.clear();
  threads_.reset();
  if (!islandSolver_ || threads <= 1) return;
  switchOffBulletProfiler();
  threads_ = std::make_unique<WorkerThreads>(threads);
  for (int t = 1; t < threads_->size(); ++t) helpers_.push_back(islandSolver_->helper());
}

void DynamicsWorld::solveIslands(btContactSolverInfo& solverInfo) {
  if (!threads_ || getNumConstraints() > 0) {
    btDiscreteDynamicsWorld::solveConstraints(solverInfo);
    return;
  }
  islandBodies_.clear();
  islandJobs_.clear();
  kinematicJobs_.clear();
  int manifolds = 0;
  // The bodies are copied: Bullet reuses its list for the next island.
  IslandList list([&](btCollisionObject** bodies, int numBodies, btPersistentManifold** islandManifolds,
                      int numManifolds) {
    const IslandJob job{islandBodies_.size(), numBodies, islandManifolds, numManifolds};
    islandBodies_.insert(islandBodies_.end(), bodies, bodies + numBodies);
    (touchesKinematic(islandManifolds, numManifolds) ? kinematicJobs_ : islandJobs_).push_back(job);
    manifolds += numManifolds;
  });
  m_constraintSolver->prepareSolve(getNumCollisionObjects(), getDispatcher()->getNumManifolds());
  m_islandManager->buildAndProcessIslands(getDispatcher(), this, &list);
  const auto solve = [&](IslandSolver& solver, const IslandJob& job) {
    solver.solveGroup(islandBodies_.data() + job.firstBody, job.numBodies, job.manifolds, job.numManifolds, nullptr,
                      0, solverInfo, getDebugDrawer(), getDispatcher());
  };
  if (islandJobs_.size() < 2 || manifolds < kSharedManifolds) {
    for (const IslandJob& job : islandJobs_) solve(*islandSolver_, job);
  } else {
    for (const auto& helper : helpers_) helper->followSettings(*islandSolver_);
    threads_->forEach(islandJobs_.size(), [&](std::size_t i, int worker) {
      solve(worker == 0 ? *islandSolver_ : *helpers_[static_cast<std::size_t>(worker - 1)], islandJobs_[i]);
    });
    for (const auto& helper : helpers_) islandSolver_->takeTally(*helper);
  }
  for (const IslandJob& job : kinematicJobs_) solve(*islandSolver_, job);
  m_constraintSolver->allSolved(solverInfo, getDebugDrawer());
}

}  // namespace tabletop
