#include "physics/step/DynamicsWorld.h"

#include <algorithm>
#include <iterator>

#include "physics/collision/ContactDispatcher.h"
#include "physics/step/FaceExits.h"
#include "physics/step/ImpactSearch.h"

// Groups apart (DynamicsWorld.h, StepGroups.h): an event cuts the step for
// its own group only. The first part finds the events group by group; when
// some groups have one and others none, it takes the whole step for every
// body, uncut (exactly what a step with no event does), and the groups with
// events are then put back to the step's start and taken again in parts,
// the rest set aside. What carries from part to part is then that of the
// whole step for the groups set aside, that of the parts for the others.
namespace tabletop {

void DynamicsWorld::saveStepStart() {
  bodyStart_.clear();
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    btRigidBody* body = m_nonStaticRigidBodies[i];
    bodyStart_.push_back({body, body->getWorldTransform(), body->getLinearVelocity(), body->getAngularVelocity(),
                          body->getDeactivationTime(), body->getActivationState()});
  }
  carriedStart_.settling[0] = settling_[0];
  carriedStart_.settling[1] = settling_[1];
  carriedStart_.sliding = sliding_;
  carriedStart_.endVelocities = endVelocities_;
  rolling_.save();
  slipEndStart_ = lastSlipEnd_;
}

// After the first part's narrow phase and its stale points: what the
// groups taken again start from.
void DynamicsWorld::savePointsStart() {
  btDispatcher* dispatcher = getDispatcher();
  manifoldStart_.resize(static_cast<std::size_t>(dispatcher->getNumManifolds()));
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    ManifoldStart& saved = manifoldStart_[static_cast<std::size_t>(m)];
    saved.manifold = manifold;
    saved.a = manifold->getBody0();
    saved.b = manifold->getBody1();
    saved.count = manifold->getNumContacts();
    for (int p = 0; p < saved.count; ++p) saved.points[p] = manifold->getContactPoint(p);
  }
  // Found by manifold through a small sorted index: sorting the saved
  // points themselves moved a kilobyte each, a twentieth of a cube field's
  // step.
  manifoldOrder_.resize(manifoldStart_.size());
  for (std::size_t k = 0; k < manifoldStart_.size(); ++k) manifoldOrder_[k] = {manifoldStart_[k].manifold, k};
  std::sort(manifoldOrder_.begin(), manifoldOrder_.end(),
            [](const auto& x, const auto& y) { return std::less<>()(x.first, y.first); });
}

DynamicsWorld::Grouping DynamicsWorld::groupEvents(const Part& part, const ImpactScan& scan, double& cut) {
  btDispatcher* dispatcher = getDispatcher();
  eventful_.clear();
  cut = earliestEvent(part, scan, &eventful_);
  // Slips that may turn round or stop inside the part (solvePart's).
  if (secondOrder_) {
    const double g = getGravity().length();
    slippingPoints(*dispatcher, g, part.length, kSlipShare, slipping_);
    slipsThatMayTurn(
        *dispatcher, slipping_, [&](const Slip& slip) { return slipCounts(slip, part.length, g); },
        touchingAnother_, mayTurn_);
    for (const Slip& slip : mayTurn_) {
      eventful_.insert(slip.manifold->getBody0());
      eventful_.insert(slip.manifold->getBody1());
    }
  }
  if (eventful_.empty()) return Grouping::kNone;
  groups_.find(m_nonStaticRigidBodies, *getBroadphase()->getOverlappingPairCache());
  groups_.spread(m_nonStaticRigidBodies, eventful_, retaken_);
  return retaken_.size() == static_cast<std::size_t>(m_nonStaticRigidBodies.size()) ? Grouping::kAll
                                                                                      : Grouping::kSome;
}

void DynamicsWorld::putBackCarried(double dt) {
  settling_[0] = carriedStart_.settling[0];
  settling_[1] = carriedStart_.settling[1];
  sliding_ = carriedStart_.sliding;
  lastSlipEnd_ = slipEndStart_;
  lastStep_ = dt;
}

void DynamicsWorld::putBackBodies(const BodySet* only) {
  for (const BodyStart& s : bodyStart_) {
    if (only != nullptr && !only->contains(s.body)) continue;
    // With its world inertia made again from the pose: the step turned it.
    s.body->setCenterOfMassTransform(s.place);
    s.body->setLinearVelocity(s.linear);
    s.body->setAngularVelocity(s.angular);
    s.body->setInterpolationLinearVelocity(s.linear);
    s.body->setInterpolationAngularVelocity(s.angular);
    s.body->setDeactivationTime(s.deactivation);
    s.body->forceActivationState(s.activation);
    s.body->clearForces();
  }
}

// The points of the manifolds still there with the same bodies.
void DynamicsWorld::putBackPoints(const BodySet* only) {
  btDispatcher* dispatcher = getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    if (only != nullptr && !only->contains(manifold->getBody0()) && !only->contains(manifold->getBody1())) continue;
    const auto found = std::lower_bound(
        manifoldOrder_.begin(), manifoldOrder_.end(), manifold,
        [](const auto& entry, const btPersistentManifold* key) { return std::less<>()(entry.first, key); });
    if (found == manifoldOrder_.end() || found->first != manifold) continue;
    const ManifoldStart& at = manifoldStart_[found->second];
    if (at.a != manifold->getBody0() || at.b != manifold->getBody1()) continue;
    manifold->setNumContacts(at.count);
    for (int p = 0; p < at.count; ++p) manifold->getContactPoint(p) = at.points[p];
  }
}

void DynamicsWorld::setAside(const BodySet& calm) {
  allBodies_ = m_nonStaticRigidBodies;
  m_nonStaticRigidBodies.resize(0);
  asideActivation_.clear();
  // The end velocities the groups taken again had at the step's start, in
  // the order of their own list.
  std::vector<std::pair<btVector3, btVector3>> ends;
  const bool known = carriedStart_.endVelocities.size() == static_cast<std::size_t>(allBodies_.size());
  for (int i = 0; i < allBodies_.size(); ++i) {
    btRigidBody* body = allBodies_[i];
    if (calm.contains(body)) {
      // Asleep, so that Bullet's islands leave it alone.
      asideActivation_.push_back(body->getActivationState());
      body->forceActivationState(ISLAND_SLEEPING);
      continue;
    }
    m_nonStaticRigidBodies.push_back(body);
    if (known) ends.push_back(carriedStart_.endVelocities[static_cast<std::size_t>(i)]);
  }
  endVelocities_ = std::move(ends);
  static_cast<ContactDispatcher*>(getDispatcher())->setAside(calm);
  impactStorage_.setAside = &calm;
}

void DynamicsWorld::bringBack() {
  std::size_t k = 0;
  for (int i = 0; i < allBodies_.size(); ++i) {
    if (aside_.contains(allBodies_[i])) allBodies_[i]->forceActivationState(asideActivation_[k++]);
  }
  m_nonStaticRigidBodies = allBodies_;
  allBodies_.resize(0);
  static_cast<ContactDispatcher*>(getDispatcher())->bringBack();
  impactStorage_.setAside = nullptr;
}

bool DynamicsWorld::crossesAside() {
  btBroadphasePairArray& pairs = getBroadphase()->getOverlappingPairCache()->getOverlappingPairArray();
  for (int p = 0; p < pairs.size(); ++p) {
    const btBroadphaseProxy* p0 = pairs[p].m_pProxy0;
    const btBroadphaseProxy* p1 = pairs[p].m_pProxy1;
    const auto* a = static_cast<const btCollisionObject*>(p0->m_clientObject);
    const auto* b = static_cast<const btCollisionObject*>(p1->m_clientObject);
    if (!(aside_.contains(a) && retaken_.contains(b)) && !(aside_.contains(b) && retaken_.contains(a))) continue;
    if (StepGroups::joins(*p0, *p1)) return true;
  }
  return false;
}

void DynamicsWorld::stepGroupsApart(double dt) {
  ++groupedSteps_;
  aside_.clear();
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    if (!retaken_.contains(m_nonStaticRigidBodies[i])) aside_.insert(m_nonStaticRigidBodies[i]);
  }
  // What the whole step leaves for the groups set aside.
  const BodySet wholeSettling = settling_[0];
  SlidingContacts wholeSliding;
  std::copy_if(sliding_.begin(), sliding_.end(), std::back_inserter(wholeSliding), [&](const ContactKey& key) {
    return !retaken_.contains(key.first) && !retaken_.contains(key.second);
  });
  const std::vector<std::pair<btVector3, btVector3>> wholeEnds = endVelocities_;
  const btAlignedObjectArray<btRigidBody*> all = m_nonStaticRigidBodies;
  // The groups with events back at the step's start, and taken again:
  // their points as the first part found them once the retaking part has
  // found its own (savePointsStart, solveContacts).
  putBackBodies(&retaken_);
  pointsBack_ = &retaken_;
  struck_.erase(std::remove_if(struck_.begin(), struck_.end(),
                               [&](const Struck& s) { return retaken_.contains(s.a) || retaken_.contains(s.b); }),
                struck_.end());
  putBackCarried(dt);
  rolling_.putBack(retaken_);
  setAside(aside_);
  takeParts(dt, false);
  bringBack();
  if (crossed_) {
    // One of them came to touch a body that had taken the step whole: the
    // whole world is taken again, as one.
    crossed_ = false;
    aside_.clear();
    ++regroupedSteps_;
    putBackBodies(nullptr);
    pointsBack_ = nullptr;
    putBackAll_ = true;
    struck_.clear();
    putBackCarried(dt);
    rolling_.putBackAll();
    endVelocities_ = carriedStart_.endVelocities;
    takeParts(dt, false);
    return;
  }
  // Each group's own: the parts' for those taken again, the whole step's
  // for the rest.
  for (int i = 0; i < all.size(); ++i) {
    if (aside_.contains(all[i]) && wholeSettling.contains(all[i])) settling_[0].insert(all[i]);
  }
  SlidingContacts merged;
  std::merge(sliding_.begin(), sliding_.end(), wholeSliding.begin(), wholeSliding.end(), std::back_inserter(merged));
  sliding_ = std::move(merged);
  std::vector<std::pair<btVector3, btVector3>> ends;
  std::size_t k = 0;
  for (int i = 0; i < all.size(); ++i) {
    if (aside_.contains(all[i])) {
      ends.push_back(static_cast<std::size_t>(i) < wholeEnds.size() ? wholeEnds[static_cast<std::size_t>(i)]
                                                                     : std::make_pair(btVector3(0, 0, 0), btVector3(0, 0, 0)));
    } else {
      ends.push_back(k < endVelocities_.size() ? endVelocities_[k] : std::make_pair(btVector3(0, 0, 0), btVector3(0, 0, 0)));
      ++k;
    }
  }
  endVelocities_ = std::move(ends);
  // The impulses carried on, on one length: the whole step's.
  if (lastStep_ > 0 && lastStep_ != dt) {
    const double ratio = dt / lastStep_;
    btDispatcher* dispatcher = getDispatcher();
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      if (!retaken_.contains(manifold->getBody0()) && !retaken_.contains(manifold->getBody1())) continue;
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        btManifoldPoint& point = manifold->getContactPoint(p);
        point.m_appliedImpulse *= ratio;
        point.m_appliedImpulseLateral1 *= ratio;
        point.m_appliedImpulseLateral2 *= ratio;
      }
    }
  }
  lastStep_ = dt;
  aside_.clear();
}

}  // namespace tabletop
