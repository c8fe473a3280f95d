#pragma once

#include <memory>
#include <vector>

#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>

#include "core/ContactSolver.h"
#include "core/WorkCount.h"
#include "physics/solver/ActiveSetSolver.h"
#include "physics/contact/BodySet.h"

namespace tabletop {

/// The MLCP solvers an IslandSolver hands to Bullet's: a base of its own,
/// so that they are made before btMLCPSolver, which keeps a pointer to the
/// active-set solver from its constructor on.
struct IslandSolverParts {
  /// Bullet's pivoting, one call at a time in the process: it reports a
  /// failure through a global flag (s_error, btDantzigLCP.cpp), which two
  /// islands pivoted at once on two threads would share.
  class LockedDantzig : public btDantzigSolver {
   public:
    bool solveMLCP(const btMatrixXu& A, const btVectorXu& b, btVectorXu& x, const btVectorXu& lo,
                   const btVectorXu& hi, const btAlignedObjectArray<int>& limitDependency, int numIterations,
                   bool useSparsity = true) override;
  };
  LockedDantzig dantzig_;
  ActiveSetSolver activeSet_{dantzig_};  // the MLCP solver: a guess first, else dantzig_
};

/// The contact solver of full physics, one island at a time (its solver
/// info's m_minimumSolverBatchSize must be 1, or small islands are batched
/// together). Each island is solved one of two ways:
///  - exactly, by Bullet's MLCP solver, with a compliance of kDirectCfm on
///    every row (the four points of a face resting on a face are
///    redundant, and without it the matrix is singular): a guess of the
///    pressing points first (ActiveSetSolver), else Dantzig's pivoting;
///  - by Bullet's sequential impulses, `iterations` sweeps.
/// ContactSolver says which: SequentialImpulse never pivots; Dantzig
/// pivots every island of at most `rowLimit` rows; Automatic pivots those
/// that carry a load (a body resting on another, where sweeps pass the
/// weight down too slowly; one with more rows gets the long sweeps below)
/// or slide on a touching point (where sweeps let
/// friction shift the load between the points unevenly, and a sliding cube
/// stopped short and turned), those of a body whose slip stopped in the
/// part before (its load shifts at once back from its leading points), a
/// round solid rolling on its rims (friction both ways at its points), and
/// sweeps the rest.
/// A ball's point (against a ball or something that does not move) slides
/// without pivoting: its rows do not act on each other, one sweep solves
/// them exactly, and pivoting only cost. Nor does a frictionless one, which
/// has no friction to shift the load. An island the pivoting fails on twice (kRetryRaise)
/// is swept (Bullet's own fallback). The push out of penetration
/// (split impulse) is pivoted on the normal rows alone; should that fail,
/// the step keeps its exact velocities and pushes nothing out.
///
/// Friction in an island solved exactly: a contact point keeps a second
/// friction row, across the first, if it could stick within the step (its
/// slip at most mu g dt); a sliding point has only the row along its slip.
/// Bullet's one row meant a body at rest had friction along one arbitrary
/// axis and none across it (a light cube under a heavy one crept across
/// it, its drift growing every second), and a second row on a sliding
/// point turned a sliding cube. Swept islands keep Bullet's one row: the
/// sweeps did not settle a cylinder standing on the table with two (it
/// jiggled at 3e-5 m/s).
class IslandSolver : private IslandSolverParts, public btMLCPSolver {
 public:
  IslandSolver(ContactSolver choice, int rowLimit, double gravity);
  /// Gravity's magnitude from now on, m/s^2.
  void setGravity(double gravity) { gravity_ = gravity < 0 ? -gravity : gravity; }

  /// Solves one island; a group with no body is skipped. Bullet ends every
  /// island pass with a call for the islands it batched, and with batches
  /// of one there are none: that empty call cost a body in free flight a
  /// tenth of its step.
  btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
                      btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info,
                      btIDebugDraw* debugDrawer, btDispatcher* dispatcher) override;

  /// A solver for another thread: the same choice, row limit and
  /// gravity. Its islands are solved as this one would solve them once it
  /// follows this one's settings (followSettings()).
  std::unique_ptr<IslandSolver> helper() const;
  /// Takes the lead's settings for the coming solve: sweeps only, the
  /// loaded and settling bodies, the impact sweeps, gravity.
  void followSettings(const IslandSolver& lead);
  /// Adds what `helper` counted (use(), work(), swept(), the long sweeps)
  /// to this solver's, and clears them in the helper.
  void takeTally(IslandSolver& helper);

  /// How the islands were solved since the solver was made.
  const SolverUse& use() const { return use_; }
  /// Rows x sweeps and rows^2 pivoted so far (WorkCount.h).
  const WorkCount& work() const { return work_; }
  /// While on, every group is swept and none is counted (the impacts'
  /// solve of every touching point, DynamicsWorld).
  void setSweepsOnly(bool on) { sweepsOnly_ = on; }
  /// Sweeps only while it lives (on `solver`, if any).
  class SweepsOnly {
   public:
    explicit SweepsOnly(IslandSolver* solver) : solver_(solver) {
      if (solver_ != nullptr) solver_->setSweepsOnly(true);
    }
    ~SweepsOnly() {
      if (solver_ != nullptr) solver_->setSweepsOnly(false);
    }
    SweepsOnly(const SweepsOnly&) = delete;
    SweepsOnly& operator=(const SweepsOnly&) = delete;

   private:
    IslandSolver* solver_;
  };
  /// The bodies of the islands swept since forgetSwept(): their friction
  /// is the sweeps', not at its bound where it slides (DynamicsWorld turns
  /// only a pivoted body by its mean spin).
  const BodySet& swept() const { return swept_; }
  /// The bodies that bear an applied force or torque through the next
  /// step: an island where one touches with friction is pivoted wherever
  /// it fits, as a load is.
  void setLoaded(BodySet bodies) { loaded_ = std::move(bodies); }
  /// The bodies whose slip stopped in the part before: their islands are
  /// pivoted in the next (setSettling()).
  void setSettling(const BodySet& bodies) { settling_ = &bodies; }
  void forgetSwept() { swept_.clear(); }
  /// An island holding a point marked as an impact (kImpactFlag) is swept
  /// this many times the iterations; the others as many as asked.
  void setImpactSweeps(int times) { impactSweeps_ = times; }
  /// Whether an island since the last call carried a load but was too
  /// large to pivot, and was given the long sweeps; clears it. Such an
  /// island needs steps of at most kLongSweepStep (World::substeps).
  bool takeLongSweeps() {
    const bool taken = longSweepsTaken_;
    longSweepsTaken_ = false;
    return taken;
  }

  /// The compliance on every row of an island solved exactly (Bullet's
  /// global CFM): small enough that a heavy stack on a light base does not
  /// sink measurably (docs/hard-cases.md).
  static constexpr double kDirectCfm = 1e-8;
  /// Dantzig's pivoting can fail on a problem that is nearly degenerate (the
  /// points of a face resting on a face carry redundant rows): a change of
  /// 1e-15 in one friction direction decided between success and failure
  /// for a truncated cone riding a cube, and the failed step, swept, set it
  /// rocking. A failed island is pivoted once more
  /// with each diagonal entry raised by this share of itself, and swept only
  /// if that fails too.
  static constexpr double kRetryRaise = 1e-9;
  /// The sweeps of an island that carries a load but has more rows than
  /// the pivoting takes (`auto`): at most this many, ending early once a
  /// sweep changes no row by more than kLongSweepTolerance (m/s), in
  /// steps of at most kLongSweepStep (s). Measured on the 55-cube pyramid
  /// (docs/hard-cases.md): at 60 Hz sweeps do not hold it at any count;
  /// in parts of 1/120 s, 200 do.
  static constexpr int kLongSweeps = 200;
  static constexpr double kLongSweepTolerance = 1e-7;
  static constexpr double kLongSweepStep = 1.0 / 120.0;

 protected:
  void convertContacts(btPersistentManifold** manifolds, int numManifolds, const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
                                        int numManifolds, btTypedConstraint** constraints, int numConstraints,
                                        const btContactSolverInfo& info, btIDebugDraw* debugDrawer) override;
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                             btPersistentManifold** manifolds, int numManifolds,
                                             btTypedConstraint** constraints, int numConstraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debugDrawer) override;
  // One sweep, then each friction impulse held within its cone
  // (holdFrictionInCones).
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int numBodies,
                                btPersistentManifold** manifolds, int numManifolds, btTypedConstraint** constraints,
                                int numConstraints, const btContactSolverInfo& info,
                                btIDebugDraw* debugDrawer) override;

  bool solveMLCP(const btContactSolverInfo& info) override;
  /// The island's problem, as Bullet's own makes it (the same b, bounds,
  /// warm start and A = J M^-1 J^T + CFM / dt), but A summed body by body
  /// over the rows that act on it: Bullet's walked every earlier row of
  /// each body through its matrix class, a third of the ten-cube stack's
  /// step once the guess (ActiveSetSolver) solved it.
  void createMLCPFast(const btContactSolverInfo& info) override;

 private:
  // How an island is solved: swept (`iterations`), pivoted, or swept long.
  enum class Way { Sweep, Pivot, LongSweeps };
  Way chooseWay(btPersistentManifold** manifolds, int numManifolds, int numConstraints) const;
  void dropSlidingCrossFriction(double timeStep);
  // Adds to each friction row what the bodies' applied torques over the
  // part (the gyroscopic term among them) do to its speed. Bullet's
  // friction rows leave it out, though its normal rows and its update of
  // the velocities take it in: a body turning about an axis not its
  // principal one, or under an applied torque, slipped where friction
  // could hold it (docs/bullet-corrections.md).
  void seeTorquesInFriction();
  // A torque's change of spin over the part below this share of the spin
  // is rounding.
  static constexpr double kRoundedTorque = 1e-12;
  // After the sweeps: each friction impulse within its point's final cone
  // (mu times the normal impulse), the bodies' velocities changed to match.
  // A sweep leaves a friction row untouched while its normal impulse is
  // zero, so friction taken while the normal pressed stayed after it let go.
  void holdFrictionInCones();
  // Pivots the whole island's problem; once more, raised, if that fails.
  bool solveWholeIsland(const btContactSolverInfo& info);

  // The push out of penetration's problem on the normal rows (solveMLCP).
  struct NormalRows {
    std::vector<int> rows;  // their indices in the whole island's problem
    btMatrixXu a;
    btVectorXu b, x, lo, hi;
    btAlignedObjectArray<int> noLimits;  // -1 each: no row bounds another
    ActiveSetSolver::RowBodies bodies;   // each row's bodies
  } split_;
  // One row's Jacobian on one body, and M^-1 times it (createMLCPFast).
  struct BodyRow {
    int row;
    double j[6], mj[6];
  };
  std::vector<std::vector<BodyRow>> bodyRows_;  // per solver body
  ActiveSetSolver::RowBodies rowBodies_;         // per row: its moving bodies' solver indices, else -1
  btMatrixXu raised_;  // the problem raised for the second try (solveWholeIsland)
  ContactSolver choice_;
  int rowLimit_;
  double gravity_;          // m/s^2, its magnitude
  bool sweepsOnly_ = false;
  Way way_ = Way::Sweep;    // how the island being solved is solved
  bool longSweepsTaken_ = false;
  BodySet swept_;
  BodySet loaded_;          // setLoaded()
  const BodySet* settling_ = nullptr;  // setSettling()
  bool counted_ = false;    // the island being solved counts in use_
  int impactSweeps_ = 1;    // setImpactSweeps()
  bool impact_ = false;     // the island being solved holds an impact
  bool guessed_ = false;    // the island just solved exactly was solved by the guess
  SolverUse use_;
  WorkCount work_;
};

}  // namespace tabletop
