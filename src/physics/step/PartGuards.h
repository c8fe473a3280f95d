#pragma once

#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "physics/contact/PointFlags.h"

namespace tabletop {

/// What a part sets on Bullet's contact points and solver for one solve,
/// and puts back as the solve ends: each a guard, so that nothing set is
/// left behind on any path (docs/step.md, "The solve").

/// Values of contact points changed for one solve, each with what it was:
/// put back last first as the guard ends, so a point held twice gets its
/// first value back. `PutBack` writes one held value back.
template <class Held, class PutBack>
class HeldForSolve {
 public:
  using Storage = std::vector<Held>;
  explicit HeldForSolve(Storage& held) : held_(held) { held_.clear(); }
  ~HeldForSolve() {
    for (auto h = held_.rbegin(); h != held_.rend(); ++h) PutBack()(*h);
    held_.clear();
  }
  HeldForSolve(const HeldForSolve&) = delete;
  HeldForSolve& operator=(const HeldForSolve&) = delete;
  Storage& storage() { return held_; }

 private:
  Storage& held_;
};

/// A point whose gap (distance) was changed for a solve, with its true gap.
struct PutBackGap {
  void operator()(const std::pair<btManifoldPoint*, btScalar>& held) const { held.first->setDistance(held.second); }
};
using HeldGaps = HeldForSolve<std::pair<btManifoldPoint*, btScalar>, PutBackGap>;

/// A point moved for a solve (FaceExits.h's levers), with its world places
/// before.
struct HeldPlace {
  btManifoldPoint* point;
  btVector3 onA, onB;
};
struct PutBackPlace {
  void operator()(const HeldPlace& held) const {
    held.point->m_positionWorldOnA = held.onA;
    held.point->m_positionWorldOnB = held.onB;
  }
};
using HeldPlaces = HeldForSolve<HeldPlace, PutBackPlace>;

/// The impulses of every point of `dispatcher`, taken when `keep` is true
/// and put back as the guard ends: a part that carries on what it was
/// given, not what it solved.
class KeptImpulses {
 public:
  using Storage = std::vector<std::pair<btManifoldPoint*, btVector3>>;
  KeptImpulses(Storage& kept, btDispatcher& dispatcher, bool keep) : kept_(kept) {
    kept_.clear();
    if (!keep) return;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        kept_.emplace_back(&point, btVector3(point.m_appliedImpulse, point.m_appliedImpulseLateral1,
                                             point.m_appliedImpulseLateral2));
      }
    }
  }
  ~KeptImpulses() {
    for (const auto& [point, impulses] : kept_) {
      point->m_appliedImpulse = impulses.x();
      point->m_appliedImpulseLateral1 = impulses.y();
      point->m_appliedImpulseLateral2 = impulses.z();
    }
  }
  KeptImpulses(const KeptImpulses&) = delete;
  KeptImpulses& operator=(const KeptImpulses&) = delete;

 private:
  Storage& kept_;
};

/// The solver's iteration count, set for one solve and put back.
class IterationsFor {
 public:
  IterationsFor(btContactSolverInfo& info, int iterations) : info_(info), before_(info.m_numIterations) {
    info_.m_numIterations = iterations;
  }
  ~IterationsFor() { info_.m_numIterations = before_; }
  IterationsFor(const IterationsFor&) = delete;
  IterationsFor& operator=(const IterationsFor&) = delete;

 private:
  btContactSolverInfo& info_;
  int before_;
};

/// Friction rows laid along a slip's line for one solve (kFirstFrictionRowOnly
/// and Bullet's initialised-direction flag): cleared as the solve ends, so
/// the next part lays its own.
class FrictionAlongLine {
 public:
  explicit FrictionAlongLine(std::vector<btManifoldPoint*> held) : held_(std::move(held)) {}
  ~FrictionAlongLine() {
    for (btManifoldPoint* point : held_) {
      point->m_contactPointFlags &= ~(BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED | kFirstFrictionRowOnly);
    }
  }
  FrictionAlongLine(const FrictionAlongLine&) = delete;
  FrictionAlongLine& operator=(const FrictionAlongLine&) = delete;

 private:
  std::vector<btManifoldPoint*> held_;
};

}  // namespace tabletop
