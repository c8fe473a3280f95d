#include "physics/step/DynamicsWorld.h"

#include <algorithm>

#include "physics/solver/IslandSolver.h"
#include "physics/step/FaceExits.h"
#include "physics/step/ImpactSearch.h"
#include "physics/step/PartGuards.h"

// Stage 6, the solve of a part (docs/step.md): the rows readied for the
// part's motion, the islands solved, what the solve leaves for the next
// part; a part in which a slip turned round is put back and cut there.
namespace tabletop {

void DynamicsWorld::shortenPart(Part& part, double length) {
  const double ratio = length / part.length;
  // The rolling resistance was given for the whole part: the rest goes back.
  for (const auto& [body, impulse] : resisted_) body->applyTorqueImpulse(-impulse * (1.0 - ratio));
  for (auto& resisted : resisted_) resisted.second *= ratio;
  for (ResistedSlip& slip : resistedSlips_) slip.friction *= ratio;
  scaleCarriedImpulses(ratio);
  part.length = length;
}

void DynamicsWorld::scaleCarriedImpulses(double ratio) {
  if (ratio == 1.0) return;
  for (int m = 0; m < getDispatcher()->getNumManifolds(); ++m) {
    btPersistentManifold* manifold = getDispatcher()->getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      btManifoldPoint& point = manifold->getContactPoint(p);
      point.m_appliedImpulse *= ratio;
      point.m_appliedImpulseLateral1 *= ratio;
      point.m_appliedImpulseLateral2 *= ratio;
    }
  }
}

void DynamicsWorld::solveUntouched(const Part& part, btContactSolverInfo& solverInfo) {
  solverInfo.m_timeStep = part.length;
  meanTurn_.clear();
  solveIslands(solverInfo);
  closing_.clear();
  noteSolved(closing_, {});
  forgetBounced();
  lastSlipEnd_.reset();
}

void DynamicsWorld::noteSolved(const ClosingPoints& closing, const std::vector<Slip>& slipping) {
  solved_ = true;
  stopped_.clear();
  for (const auto& [manifold, point] : closing) {
    if (!(point->getAppliedImpulse() > 0)) continue;
    stopped_.insert(manifold->getBody0());
    stopped_.insert(manifold->getBody1());
  }
  if (!stopped_.empty()) spreadStops();
  findSlipStops(slipping);
}

// Solves the part. With kMayCutAtSlip, a part in which a slip turned round is
// put back as it was before the solve and shortened to that time, and the
// turn is returned: the part is to be solved again.
SlipTurn DynamicsWorld::solvePart(Part& part, btContactSolverInfo& solverInfo, const ImpactScan& scan,
                                  PartSolve how) {
  btDispatcher* dispatcher = getDispatcher();
  SlipTurn turn{part.length, nullptr, nullptr, btVector3(0, 0, 0), false};
  bool impacts = false;
  {
    // A part shorter than the step (cut at an impact, or what was left
    // after one) carries on what it was given, not what it solved: its
    // impulses also hold velocity corrections that do not grow with the
    // part, and the next, longer part would scale them up with its length.
    // A part cut where a slip turned (the second solve, at least a
    // hundredth of the part, with no impact in it) carries on what it
    // solved: its loads, which the rolling resistance of the next part reads.
    const KeptImpulses kept(partCarried_, *dispatcher,
                            part.length < stepLength_ && how != PartSolve::kAfterSlipCut);
    solverInfo.m_timeStep = part.length;
    const int iterations = solverInfo.m_numIterations;
    impacts = markImpacts(solverInfo.m_timeStep);
    // tabletop's solver gives an impact's own islands the impact sweeps.
    const IterationsFor sweeps(solverInfo, impacts && !islandSolver_ ? kImpactSweeps * iterations : iterations);
    // The points closing at the part's start that meet inside it even at
    // that speed: a body one of them stops changes its velocity at once,
    // not smoothly. (A part cut at an impact reaches its point only at its end.)
    ClosingPoints& closing = closing_;
    closing.clear();
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p) {
        const btManifoldPoint& point = manifold->getContactPoint(p);
        const double speed = closingSpeed(*manifold, point);
        if (speed > stopSpeed() && point.getDistance() <= speed * part.length) closing.emplace_back(manifold, &point);
      }
    }
    const double g = getGravity().length();
    std::vector<Slip>& slipping = slipping_;
    slipping.clear();
    if (secondOrder_) slippingPoints(*dispatcher, g, part.length, kSlipShare, slipping);
    // A body one of those points may stop keeps Bullet's rows on its other
    // points: held at the mean, they let a cone's rim, landing over a box's
    // edge, go into the box (docs/bullet-corrections.md).
    meanTurn_.clear();
    stopping_.clear();
    for (const auto& [manifold, point] : closing) {
      stopping_.insert(manifold->getBody0());
      stopping_.insert(manifold->getBody1());
    }
    HeldGaps gaps(heldGaps_);
    HeldPlaces places(heldPlaces_);
    if (secondOrder_) scan.holdMeanVelocity(part.length, stopping_, gaps.storage(), meanTurn_);
    holdEdgeCurvature(*dispatcher, part.length, stepLength_, secondOrder_, gaps.storage(), pointBoxes_);
    holdEdgeLevers(*dispatcher, part.length, places.storage(), pointBoxes_);
    const auto counts = [&](const Slip& slip) { return slipCounts(slip, part.length, g); };
    std::vector<Slip>& mayTurn = mayTurn_;
    mayTurn.clear();
    if (how == PartSolve::kMayCutAtSlip && !impacts) slipsThatMayTurn(*dispatcher, slipping, counts, touchingAnother_, mayTurn);
    if (!mayTurn.empty()) partStart_.save(m_nonStaticRigidBodies, *dispatcher);
    // The island pass sorts Bullet's union-find in place, and a second pass
    // over it scrambles the islands (Restitution.cpp): a part solved again
    // has its islands found afresh.
    if (how == PartSolve::kAfterSlipCut) calculateSimulationIslands();
    if (islandSolver_) islandSolver_->forgetSwept();
    solveIslands(solverInfo);
    if (!mayTurn.empty()) turn = earliestSlipTurn(mayTurn, g, part.length, kSlipShare);
    if (!turn.manifold) noteSolved(closing, slipping);
  }
  if (impacts) forgetImpacts();
  if (!turn.manifold) {
    forgetBounced();
    return turn;
  }
  partStart_.restore();
  shortenPart(part, turn.time);
  return turn;
}

// A slip counts if its contact slid through the part before, or if it is
// more than friction takes in the part (a push's): rolling resistance
// makes a small slip of its own at a part's start, which friction stops at
// once, and cutting there cut every part of a rolling ball.
bool DynamicsWorld::slipCounts(const Slip& slip, double length, double g) const {
  return slid(sliding_, contactOf(*slip.manifold)) ||
         slip.velocity.length() > slip.point->m_combinedFriction * g * length;
}

// After a part cut where a slip turned round or stopped, and solved again.
void DynamicsWorld::noteSlipEnd(const Part& part, const SlipTurn& turned) {
  // Held along one line only where the contact slid along one: each
  // point of a spinning face slips its own way, and its rows laid along
  // one point's line braked a spun box on the slab too weakly.
  const ContactKey key = contactOf(*turned.manifold);
  const bool alongOneLine = std::all_of(slipping_.begin(), slipping_.end(), [&](const Slip& slip) {
    return contactOf(*slip.manifold) != key || slip.velocity.normalized().dot(turned.along) > kOneLine;
  });
  if (alongOneLine) lastSlipEnd_ = SlipEnd{key, turned.along, turned.reversed};
  // A slip that ends the part at zero does not slide into the next one,
  // where a slip made at its start (by rolling resistance) is no stop; one
  // left short of zero (the time is estimated) is cut again there.
  const double still = kSlipShare * turned.point->m_combinedFriction * getGravity().length() * part.length;
  if (slipSpeed(*turned.manifold, *turned.point) <= still) {
    const auto [first, last] = std::equal_range(sliding_.begin(), sliding_.end(), contactOf(*turned.manifold));
    sliding_.erase(first, last);
  }
}

}  // namespace tabletop
