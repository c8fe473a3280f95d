#include "physics/collision/ContactDispatcher.h"

#include <algorithm>

#include "physics/collision/PairTable.h"

namespace tabletop {

ContactDispatcher::ContactDispatcher(btCollisionConfiguration* configuration)
    : btCollisionDispatcher(configuration) {
  setDispatcherFlags(getDispatcherFlags() & ~CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD);
  setNearCallback(&ContactDispatcher::nearCallback);
  // Bullet's default configuration makes every convex pair with one
  // create function (polyhedral clipping with SAT axes, else GJK); a copy
  // is given Bullet's multipoint defaults.
  auto* convex = configuration->getCollisionAlgorithmCreateFunc(CONVEX_HULL_SHAPE_PROXYTYPE, CONVEX_HULL_SHAPE_PROXYTYPE);
  multipoint_ = std::make_unique<btConvexConvexAlgorithm::CreateFunc>(
      *static_cast<const btConvexConvexAlgorithm::CreateFunc*>(convex));
  multipoint_->m_numPerturbationIterations = 3;
  multipoint_->m_minimumPointsPerturbationThreshold = 3;
  // Each row of the pair table that is not Bullet's own, both ways round.
  for (const PairRule* rule = pairRulesBegin(); rule != pairRulesEnd(); ++rule) {
    btCollisionAlgorithmCreateFunc* finder = nullptr;
    switch (rule->finder) {
      case PointFinder::kBullet: continue;
      case PointFinder::kSolidOnPlane: finder = &planeFinder_; break;
      case PointFinder::kSolidOnFace:
        faceFinders_.push_back(std::make_unique<SolidOnFaceAlgorithm::CreateFunc>(
            rule->otherwise == FaceFallback::kMultipointGjk ? multipoint_.get() : convex));
        finder = faceFinders_.back().get();
        break;
    }
    registerCollisionCreateFunc(rule->a, rule->b, finder);
    registerCollisionCreateFunc(rule->b, rule->a, finder);
  }
}

void ContactDispatcher::nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher,
                                     const btDispatcherInfo& info) {
  const auto* object0 = static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
  const auto* object1 = static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
  if (!dispatcher.needsCollision(object0, object1)) return;
  if (const BodySet* aside = static_cast<ContactDispatcher&>(dispatcher).aside_) {
    if (aside->contains(object0) || aside->contains(object1)) return;
  }
  const btCollisionObjectWrapper wrap0(nullptr, object0->getCollisionShape(), object0, object0->getWorldTransform(),
                                       -1, -1);
  const btCollisionObjectWrapper wrap1(nullptr, object1->getCollisionShape(), object1, object1->getWorldTransform(),
                                       -1, -1);
  // The pair keeps its algorithm from step to step.
  if (pair.m_algorithm == nullptr) {
    pair.m_algorithm = dispatcher.findAlgorithm(&wrap0, &wrap1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  }
  if (pair.m_algorithm == nullptr) return;
  // Only a ContactDispatcher sets this callback.
  auto& self = static_cast<ContactDispatcher&>(dispatcher);
  ContactResult result(&wrap0, &wrap1, self.found_, self.offered_);
  // Two spheres: Bullet's algorithm reports them only once they overlap,
  // unless asked for points this far apart. Every other pair is found up
  // to the breaking threshold ahead of touching, and an impact between
  // spheres is placed at its own time like any other (DynamicsWorld).
  if (!pairRule(*object0, *object1).seenAhead) {
    result.m_closestPointDistanceThreshold = gContactBreakingThreshold;
  }
  if (info.m_dispatchFunc == btDispatcherInfo::DISPATCH_DISCRETE) {
    pair.m_algorithm->processCollision(&wrap0, &wrap1, info, &result);
    result.keepWidestFlatFour();
  } else {
    const btScalar impact = pair.m_algorithm->calculateTimeOfImpact(const_cast<btCollisionObject*>(object0),
                                                                    const_cast<btCollisionObject*>(object1), info,
                                                                    &result);
    if (impact < info.m_timeOfImpact) info.m_timeOfImpact = impact;
  }
}

void ContactDispatcher::setAside(const BodySet& bodies) {
  aside_ = &bodies;
  int kept = 0;
  for (int m = 0; m < m_manifoldsPtr.size(); ++m) {
    btPersistentManifold* manifold = m_manifoldsPtr[m];
    if (bodies.contains(manifold->getBody0()) || bodies.contains(manifold->getBody1())) {
      asideManifolds_.push_back(manifold);
    } else {
      manifold->m_index1a = kept;
      m_manifoldsPtr[kept++] = manifold;
    }
  }
  m_manifoldsPtr.resize(kept);
}

void ContactDispatcher::bringBack() {
  for (btPersistentManifold* manifold : asideManifolds_) {
    manifold->m_index1a = m_manifoldsPtr.size();
    m_manifoldsPtr.push_back(manifold);
  }
  asideManifolds_.clear();
  aside_ = nullptr;
}

void ContactDispatcher::releaseManifold(btPersistentManifold* manifold) {
  const auto at = std::find(asideManifolds_.begin(), asideManifolds_.end(), manifold);
  if (at != asideManifolds_.end()) {
    // Back in the list for Bullet to take it out.
    asideManifolds_.erase(at);
    manifold->m_index1a = m_manifoldsPtr.size();
    m_manifoldsPtr.push_back(manifold);
  }
  btCollisionDispatcher::releaseManifold(manifold);
}

}  // namespace tabletop
