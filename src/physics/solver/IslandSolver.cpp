#include "physics/solver/IslandSolver.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "physics/contact/ContactKinematics.h"
#include "physics/shapes/RoundEnds.h"
#include "physics/shapes/ShapeKinds.h"
#include "physics/contact/PointFlags.h"

namespace tabletop {
namespace {

// A touching point slides when its bodies slip over each other faster
// than this, m/s.
constexpr double kSlideSpeed = 1e-3;
// A touching point rolls when its bodies turn over each other, about an
// axis across its normal, faster than this, rad/s.
constexpr double kRollRate = 1e-2;

// Whether a point's rows are independent of each other: each body at it is
// a ball (whose normal passes through its centre, and whose inertia is the
// same about every axis) or does not move. One sweep then solves them
// exactly, and pivoting buys nothing.
bool uncoupled(const btPersistentManifold& manifold) {
  const auto plain = [](const btCollisionObject* o) { return isBall(*o) || !isMoving(*o); };
  return plain(manifold.getBody0()) && plain(manifold.getBody1());
}

// Whether either body at a point is a round solid (a cylinder or a cone),
// which rolls on its rims.
bool round(const btPersistentManifold& manifold) {
  const auto isRound = [](const btCollisionObject* o) { return isMoving(*o) && roundEnds(*o->getCollisionShape()); };
  return isRound(manifold.getBody0()) || isRound(manifold.getBody1());
}

// How fast the bodies at a point turn over each other about an axis
// across its normal, rad/s.
double rollRate(const btPersistentManifold& manifold, const btManifoldPoint& point) {
  const auto spin = [](const btCollisionObject* o) {
    const btRigidBody* body = btRigidBody::upcast(o);
    return body ? body->getAngularVelocity() : btVector3(0, 0, 0);
  };
  const btVector3 relative = spin(manifold.getBody0()) - spin(manifold.getBody1());
  const btVector3& n = point.m_normalWorldOnB;
  return (relative - n * n.dot(relative)).length();
}

}  // namespace

bool IslandSolverParts::LockedDantzig::solveMLCP(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x,
                                                 const btVectorXu& lo, const btVectorXu& hi,
                                                 const btAlignedObjectArray<int>& limitDependency, int numIterations,
                                                 bool useSparsity) {
  // The one lock of the process (one for Bullet's one flag).
  static std::mutex pivoting;
  const std::lock_guard<std::mutex> lock(pivoting);
  return btDantzigSolver::solveMLCP(A, b, x, lo, hi, limitDependency, numIterations, useSparsity);
}

IslandSolver::IslandSolver(ContactSolver choice, int rowLimit, double gravity)
    : btMLCPSolver(&activeSet_), choice_(choice), rowLimit_(rowLimit), gravity_(std::abs(gravity)) {}

std::unique_ptr<IslandSolver> IslandSolver::helper() const {
  return std::make_unique<IslandSolver>(choice_, rowLimit_, gravity_);
}

void IslandSolver::followSettings(const IslandSolver& lead) {
  gravity_ = lead.gravity_;
  sweepsOnly_ = lead.sweepsOnly_;
  loaded_.clear();
  loaded_.insertAll(lead.loaded_);
  settling_ = lead.settling_;
  impactSweeps_ = lead.impactSweeps_;
}

void IslandSolver::takeTally(IslandSolver& helper) {
  SolverUse& from = helper.use_;
  use_.direct += from.direct;
  use_.guessed += from.guessed;
  use_.swept += from.swept;
  use_.longSwept += from.longSwept;
  use_.fallbacks += from.fallbacks;
  use_.largestIsland = std::max(use_.largestIsland, from.largestIsland);
  work_ += helper.work_;
  swept_.insertAll(helper.swept_);
  longSweepsTaken_ = longSweepsTaken_ || helper.longSweepsTaken_;
  helper.use_ = {};
  helper.work_ = {};
  helper.swept_.clear();
  helper.longSweepsTaken_ = false;
}

IslandSolver::Way IslandSolver::chooseWay(btPersistentManifold** manifolds, int numManifolds,
                                         int numConstraints) const {
  if (choice_ == ContactSolver::SequentialImpulse || numConstraints != 0) return Way::Sweep;
  // Rows before setup: a normal and at most two friction rows per point.
  long rows = 0;
  for (int m = 0; m < numManifolds; ++m) rows += 3L * manifolds[m]->getNumContacts();
  const bool fits = rows <= rowLimit_;
  if (choice_ == ContactSolver::Dantzig) return fits ? Way::Pivot : Way::Sweep;
  // A body under an applied load with friction on it is pivoted: held by
  // friction against a sideways force, a box on its four corners crept
  // 42 um and sank 53 um in 5 s at 30 Hz under ten sweeps.
  for (int m = 0; !loaded_.empty() && m < numManifolds; ++m) {
    const btPersistentManifold* manifold = manifolds[m];
    if (!loaded_.contains(manifold->getBody0()) && !loaded_.contains(manifold->getBody1())) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      if (manifold->getContactPoint(p).m_combinedFriction > 0) return fits ? Way::Pivot : Way::LongSweeps;
    }
  }
  // A body whose slip stopped in the part before is pivoted: its load
  // shifts at once from its leading points, where the friction put it, to
  // even, and sweeps started from the old share left it there in part (a
  // cylinder lying on its side, pushed along its axis, pitched 0.05 degree
  // as it stopped at 30 Hz).
  for (int m = 0; settling_ != nullptr && !settling_->empty() && m < numManifolds; ++m) {
    const btPersistentManifold* manifold = manifolds[m];
    if (settling_->contains(manifold->getBody0()) || settling_->contains(manifold->getBody1())) {
      return fits ? Way::Pivot : Way::LongSweeps;
    }
  }
  if (gravity_ == 0) return Way::Sweep;
  bool slides = false;
  bool rolls = false;
  bool sunk = false;
  for (int m = 0; m < numManifolds; ++m) {
    const btPersistentManifold* manifold = manifolds[m];
    const bool bothDynamic = isMoving(*manifold->getBody0()) && isMoving(*manifold->getBody1());
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold->getContactPoint(p);
      if (point.getDistance() > kLoadTouching) continue;
      // A load is pivoted wherever its points are: a body pressed into
      // the table under a heavier one must not be left to the sweeps.
      if (bothDynamic && std::abs(point.m_normalWorldOnB.y()) >= kLoadNormal) {
        return fits ? Way::Pivot : Way::LongSweeps;
      }
      sunk = sunk || point.getDistance() < -kLoadTouching;
      const bool sliding = point.m_combinedFriction > 0 && slipSpeed(*manifold, point) > kSlideSpeed;
      slides = slides || (sliding && !uncoupled(*manifold));
      rolls = rolls || (point.m_combinedFriction > 0 && !sliding && rollRate(*manifold, point) > kRollRate &&
                        round(*manifold));
    }
  }
  // Pivoted: a slide with no point sunk in, and a resting island with one
  // (ten sweeps over a cone lying on its side left its narrow end closing
  // into the table, 0.17 mm deeper every other step: 0.86 mm at 60 Hz).
  // Also pivoted: a round solid rolling on its rims with no point sunk
  // in, whose points need friction both ways while they stick (a cone
  // rolling in a circle about its apex; swept with one row a point, it
  // slipped across it and lost 0.5% of its energy a second at any rate).
  // Swept: a slide with a point sunk in (a landing), left to the sweeps'
  // split impulse, and a resting island with none, which they hold.
  const bool clearSlide = slides && !sunk;
  const bool clearRoll = rolls && !slides && !sunk;
  const bool sunkRest = !slides && sunk;
  return fits && (clearSlide || clearRoll || sunkRest) ? Way::Pivot : Way::Sweep;
}

void IslandSolver::convertContacts(btPersistentManifold** manifolds, int numManifolds,
                                   const btContactSolverInfo& info) {
  btSequentialImpulseConstraintSolver::convertContacts(manifolds, numManifolds, info);
  seeTorquesInFriction();
  if (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) dropSlidingCrossFriction(info.m_timeStep);
}

void IslandSolver::seeTorquesInFriction() {
  // Bullet's gyroscopic term turns a spin to the body's frame and back,
  // leaving rounding where there is no term (a cube): that is left out.
  const auto turned = [](const btSolverBody& body) {
    return body.m_originalBody &&
           body.m_externalTorqueImpulse.length2() > kRoundedTorque * kRoundedTorque * body.m_angularVelocity.length2();
  };
  for (int i = 0; i < m_tmpSolverContactFrictionConstraintPool.size(); ++i) {
    btSolverConstraint& row = m_tmpSolverContactFrictionConstraintPool[i];
    const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    btScalar missed = 0;
    if (turned(a)) missed += row.m_relpos1CrossNormal.dot(a.m_externalTorqueImpulse);
    if (turned(b)) missed += row.m_relpos2CrossNormal.dot(b.m_externalTorqueImpulse);
    row.m_rhs -= missed * row.m_jacDiagABInv;
  }
}

void IslandSolver::dropSlidingCrossFriction(double timeStep) {
  // Bullet lays out each point's rows as its normal row, whose friction
  // index is its first friction row, and that row followed by the second.
  const int frictionRows = m_tmpSolverContactFrictionConstraintPool.size();
  for (int c = 0; c < m_tmpSolverContactConstraintPool.size(); ++c) {
    const int first = m_tmpSolverContactConstraintPool[c].m_frictionIndex;
    if (first + 1 >= frictionRows || m_tmpSolverContactFrictionConstraintPool[first + 1].m_frictionIndex != c) continue;
    const btSolverConstraint& along = m_tmpSolverContactFrictionConstraintPool[first];
    if (along.m_jacDiagABInv == 0) continue;
    // The first row lies along the slip when there is one (its right-hand
    // side is the slip speed times the row's effective mass), or along the
    // line a slip that just turned round slides on (DynamicsWorld).
    const auto* point = static_cast<const btManifoldPoint*>(m_tmpSolverContactConstraintPool[c].m_originalContactPoint);
    const bool turned = point && (point->m_contactPointFlags & kFirstFrictionRowOnly);
    const double slip = std::abs(along.m_rhs / along.m_jacDiagABInv);
    if (!turned && slip <= along.m_friction * gravity_ * timeStep) continue;
    btSolverConstraint& across = m_tmpSolverContactFrictionConstraintPool[first + 1];
    across.m_friction = 0;
    across.m_lowerLimit = 0;
    across.m_upperLimit = 0;
  }
}

bool IslandSolver::solveWholeIsland(const btContactSolverInfo& info) {
  const ActiveSetSolver::Answer answer = activeSet_.solve(m_A, m_b, m_x, m_lo, m_hi, m_limitDependencies, &rowBodies_);
  guessed_ = answer == ActiveSetSolver::Answer::kByGuess;
  if (answer != ActiveSetSolver::Answer::kNone) return true;
  raised_ = m_A;
  for (int i = 0; i < raised_.rows(); ++i) raised_.setElem(i, i, raised_(i, i) * (1.0 + kRetryRaise));
  m_x.setZero();
  if (dantzig_.solveMLCP(raised_, m_b, m_x, m_lo, m_hi, m_limitDependencies, info.m_numIterations)) return true;
  m_x.setZero();
  guessed_ = activeSet_.solveStickingTurns(m_A, m_b, m_x, m_lo, m_hi, m_limitDependencies, &rowBodies_);
  return guessed_;
}

bool IslandSolver::solveMLCP(const btContactSolverInfo& info) {
  if (m_A.rows() == 0) return true;
  if (!info.m_splitImpulse) return solveWholeIsland(info);
  // The normal rows: those whose limits hang on no other row (a friction
  // row's hang on its normal's). Kept in members: this runs every step of
  // every pivoted island.
  std::vector<int>& normals = split_.rows;
  normals.clear();
  for (int i = 0; i < m_limitDependencies.size(); ++i) {
    if (m_limitDependencies[i] < 0) normals.push_back(i);
  }
  const int n = static_cast<int>(normals.size());
  btMatrixXu& a = split_.a;
  btVectorXu &b = split_.b, &x = split_.x, &lo = split_.lo, &hi = split_.hi;
  a.resize(n, n);
  b.resize(n), x.resize(n), lo.resize(n), hi.resize(n);
  split_.bodies.resize(n);
  const int all = m_A.cols();
  const double* whole = m_A.getBufferPointer();
  double* normalRows = a.getBufferPointerWritable();
  for (int r = 0; r < n; ++r) {
    const double* from = whole + static_cast<std::size_t>(normals[r]) * all;
    double* to = normalRows + static_cast<std::size_t>(r) * n;
    // Every entry written, a zero of either sign as +0.
    for (int c = 0; c < n; ++c) to[c] = from[normals[c]] != 0 ? from[normals[c]] : 0.0;
    b[r] = m_bSplit[normals[r]];
    split_.bodies[r] = rowBodies_[normals[r]];
    x[r] = 0;
    lo[r] = m_lo[normals[r]];
    hi[r] = m_hi[normals[r]];
  }
  if (!solveWholeIsland(info)) return false;
  // The push out of penetration along the normals alone, solved on their
  // rows only: friction rows pushing sideways would move bodies no force
  // moved, and held at zero they made the pivoting fail (a 1.4 kg cube
  // tipping off a 70 g cone's rim at 60 Hz: the island was swept, the
  // cone sank through the table). Should it fail still, the step keeps
  // its exact velocities and takes out no penetration.
  m_xSplit.resize(m_A.rows());
  m_xSplit.setZero();
  btAlignedObjectArray<int>& none = split_.noLimits;
  none.resize(n);
  for (int r = 0; r < n; ++r) none[r] = -1;
  if (n > 0 && activeSet_.solve(a, b, x, lo, hi, none, &split_.bodies) != ActiveSetSolver::Answer::kNone) {
    for (int r = 0; r < n; ++r) m_xSplit[normals[r]] = x[r];
  }
  return true;
}

void IslandSolver::createMLCPFast(const btContactSolverInfo& info) {
  const int n = m_allConstraintPtrArray.size();
  m_b.resize(n), m_bSplit.resize(n), m_lo.resize(n), m_hi.resize(n), m_x.resize(n), m_xSplit.resize(n);
  const bool warm = (info.m_solverMode & SOLVER_USE_WARMSTARTING) != 0;
  const auto numBodies = static_cast<std::size_t>(m_tmpSolverBodyPool.size());
  if (bodyRows_.size() < numBodies) bodyRows_.resize(numBodies);
  for (std::size_t s = 0; s < numBodies; ++s) bodyRows_[s].clear();
  const auto addSide = [this](int row, int solverBody, const btVector3& normal, const btVector3& lever) {
    const btRigidBody* body = m_tmpSolverBodyPool[solverBody].m_originalBody;
    if (body == nullptr) return;  // the fixed body
    const btVector3 linear = normal * body->getInvMass();
    const btVector3 angular = lever * body->getInvInertiaTensorWorld();
    BodyRow side{row, {}, {}};
    for (int r = 0; r < 3; ++r) {
      side.j[r] = normal[r], side.j[r + 3] = lever[r];
      side.mj[r] = linear[r], side.mj[r + 3] = angular[r];
    }
    bodyRows_[static_cast<std::size_t>(solverBody)].push_back(side);
  };
  rowBodies_.resize(n);
  const auto moving = [this](int solverBody) { return m_tmpSolverBodyPool[solverBody].m_originalBody ? solverBody : -1; };
  for (int i = 0; i < n; ++i) {
    const btSolverConstraint& c = *m_allConstraintPtrArray[i];
    rowBodies_[i] = {moving(c.m_solverBodyIdA), moving(c.m_solverBodyIdB)};
    const bool none = btFuzzyZero(c.m_jacDiagABInv);
    m_b[i] = none ? 0 : c.m_rhs / c.m_jacDiagABInv;
    m_bSplit[i] = none ? 0 : c.m_rhsPenetration / c.m_jacDiagABInv;
    m_lo[i] = c.m_lowerLimit;
    m_hi[i] = c.m_upperLimit;
    m_x[i] = warm ? c.m_appliedImpulse : 0;
    m_xSplit[i] = warm ? c.m_appliedPushImpulse : 0;
    // A row held at zero (a sliding point's friction across its slip,
    // dropSlidingCrossFriction) has no impulse to give: its entries of A
    // are left at zero. Neither solver reads them: the guess takes in only
    // rows with room between their bounds, and Dantzig's pivoting keeps
    // such a row at its bound and never lets it limit a step.
    if (c.m_lowerLimit == 0 && c.m_upperLimit == 0) continue;
    addSide(i, c.m_solverBodyIdA, c.m_contactNormal1, c.m_relpos1CrossNormal);
    addSide(i, c.m_solverBodyIdB, c.m_contactNormal2, c.m_relpos2CrossNormal);
  }
  m_A.resize(n, n);
  double* a = m_A.getBufferPointerWritable();
  if (a == nullptr) return;
  // A is symmetric: its lower triangle is summed over the bodies (a body's
  // rows are listed in rising order, so row p's come at or below row q's),
  // then copied above.
  const auto at = [a, n](int row, int column) -> double& { return a[static_cast<std::size_t>(row) * n + column]; };
  for (int i = 0; i < n; ++i) std::fill(&at(i, 0), &at(i, 0) + i + 1, 0.0);
  for (std::size_t s = 0; s < numBodies; ++s) {
    const std::vector<BodyRow>& rows = bodyRows_[s];
    for (std::size_t p = 0; p < rows.size(); ++p) {
      for (std::size_t q = 0; q <= p; ++q) {
        double v = 0;
        for (int k = 0; k < 6; ++k) v += rows[p].mj[k] * rows[q].j[k];
        at(rows[p].row, rows[q].row) += v;
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < i; ++j) at(j, i) = at(i, j);
    at(i, i) += info.m_globalCfm / info.m_timeStep;
  }
}

btScalar IslandSolver::solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
                                  int numManifolds, btTypedConstraint** constraints, int numConstraints,
                                  const btContactSolverInfo& info, btIDebugDraw* debugDrawer, btDispatcher* dispatcher) {
  if (numBodies == 0) return 0;
  return btMLCPSolver::solveGroup(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info,
                                  debugDrawer, dispatcher);
}

btScalar IslandSolver::solveGroupCacheFriendlySetup(btCollisionObject** bodies, int numBodies,
                                                    btPersistentManifold** manifolds, int numManifolds,
                                                    btTypedConstraint** constraints, int numConstraints,
                                                    const btContactSolverInfo& info, btIDebugDraw* debugDrawer) {
  way_ = sweepsOnly_ ? Way::Sweep : chooseWay(manifolds, numManifolds, numConstraints);
  counted_ = !sweepsOnly_ && numManifolds > 0;
  impact_ = false;
  for (int m = 0; impactSweeps_ > 1 && !impact_ && m < numManifolds; ++m) {
    for (int p = 0; p < manifolds[m]->getNumContacts(); ++p) {
      if (manifolds[m]->getContactPoint(p).m_contactPointFlags & kImpactFlag) impact_ = true;
    }
  }
  if (counted_) use_.largestIsland = std::max<long>(use_.largestIsland, numBodies);
  if (way_ == Way::LongSweeps) longSweepsTaken_ = true;
  if (way_ != Way::Pivot && !sweepsOnly_) {
    for (int i = 0; i < numBodies; ++i) swept_.insert(bodies[i]);
  }
  if (way_ == Way::Pivot) {
    btContactSolverInfo direct = info;
    direct.m_globalCfm = kDirectCfm;
    direct.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS | SOLVER_ENABLE_FRICTION_DIRECTION_CACHING;
    return btMLCPSolver::solveGroupCacheFriendlySetup(bodies, numBodies, manifolds, numManifolds, constraints,
                                                      numConstraints, direct, debugDrawer);
  }
  return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
}

btScalar IslandSolver::solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                                         btPersistentManifold** manifolds, int numManifolds,
                                                         btTypedConstraint** constraints, int numConstraints,
                                                         const btContactSolverInfo& info, btIDebugDraw* debugDrawer) {
  const double rows = m_tmpSolverContactConstraintPool.size() + m_tmpSolverContactFrictionConstraintPool.size() +
                      m_tmpSolverNonContactConstraintPool.size() + m_tmpSolverContactRollingFrictionConstraintPool.size();
  if (impact_ && way_ != Way::Pivot) {
    btContactSolverInfo more = info;
    more.m_numIterations *= impactSweeps_;
    impact_ = false;
    return solveGroupCacheFriendlyIterations(bodies, numBodies, manifolds, numManifolds, constraints, numConstraints,
                                             more, debugDrawer);
  }
  if (way_ == Way::LongSweeps) {
    if (counted_) ++use_.longSwept;
    btContactSolverInfo many = info;
    many.m_numIterations = std::max(info.m_numIterations, kLongSweeps);
    work_.sweptRows += rows * many.m_numIterations;
    // The scene's own tolerance when it asks for a finer one (0: none).
    const btScalar tolerance2 = kLongSweepTolerance * kLongSweepTolerance;
    const btScalar own = info.m_leastSquaresResidualThreshold;
    many.m_leastSquaresResidualThreshold = own > 0 ? std::min(own, tolerance2) : tolerance2;
    return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyIterations(
        bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, many, debugDrawer);
  }
  if (way_ == Way::Sweep) {
    if (counted_) ++use_.swept;
    work_.sweptRows += rows * info.m_numIterations;
    return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyIterations(
        bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
  }
  work_.pivotedRows += rows * rows;
  const int fallbacksBefore = getNumFallbacks();
  const btScalar result = btMLCPSolver::solveGroupCacheFriendlyIterations(
      bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
  if (getNumFallbacks() > fallbacksBefore) {
    ++use_.fallbacks;
  } else {
    ++use_.direct;
    if (guessed_) ++use_.guessed;
  }
  return result;
}

btScalar IslandSolver::solveSingleIteration(int iteration, btCollisionObject** bodies, int numBodies,
                                            btPersistentManifold** manifolds, int numManifolds,
                                            btTypedConstraint** constraints, int numConstraints,
                                            const btContactSolverInfo& info, btIDebugDraw* debugDrawer) {
  const btScalar residual = btSequentialImpulseConstraintSolver::solveSingleIteration(
      iteration, bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
  // Not in the long sweeps: there the 55-cube pyramid drifted 0.55 mm
  // (held to 0.5 mm; not traced).
  if (way_ == Way::Sweep) holdFrictionInCones();
  return residual;
}

void IslandSolver::holdFrictionInCones() {
  for (int i = 0; i < m_tmpSolverContactFrictionConstraintPool.size(); ++i) {
    btSolverConstraint& row = m_tmpSolverContactFrictionConstraintPool[i];
    const btScalar normal = m_tmpSolverContactConstraintPool[row.m_frictionIndex].m_appliedImpulse;
    const btScalar bound = row.m_friction * std::max(normal, btScalar(0));
    const btScalar held = std::clamp(row.m_appliedImpulse, -bound, bound);
    const btScalar change = held - row.m_appliedImpulse;
    if (change == 0) continue;
    btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    a.internalApplyImpulse(row.m_contactNormal1 * a.internalGetInvMass(), row.m_angularComponentA, change);
    b.internalApplyImpulse(row.m_contactNormal2 * b.internalGetInvMass(), row.m_angularComponentB, change);
    row.m_appliedImpulse = held;
  }
}

}  // namespace tabletop
