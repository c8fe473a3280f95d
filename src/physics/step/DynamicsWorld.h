#pragma once

#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "core/WorkCount.h"
#include "core/WorkerThreads.h"

#include "physics/contact/BodySet.h"
#include "physics/solver/ContactIslands.h"
#include "physics/collision/ContactResult.h"
#include "physics/step/FaceExits.h"
#include "physics/step/FreeFlight.h"
#include "physics/step/RollingLines.h"
#include "physics/step/ImpactSearch.h"
#include "physics/step/KeptOut.h"
#include "physics/step/PartGuards.h"
#include "physics/step/SlipEvents.h"
#include "physics/step/StepGroups.h"

namespace tabletop {

class IslandSolver;

/// The step of full physics: Bullet's discrete dynamics world, stepped by
/// tabletop's own ordered stages (Step.cpp lists them; docs/step.md says
/// what each does and why). Bullet finds the contacts (shapes, broadphase,
/// narrow phase) and holds the bodies; tabletop decides when a part of a
/// step ends (impacts, slips, bodies leaving a face), how touching points
/// bounce, how each island is solved (solver/IslandSolver.h) and how
/// positions follow the velocities:
///  - a step is taken in parts, each ending at the next event inside it,
///    at most kMaxParts;
///  - touching points closing at an impact's speed bounce at a part's start
///    in a solve of their own (Restitution.cpp);
///  - rolling and spinning resistance are one isotropic angular impulse per
///    contact (RollingResistance.cpp);
///  - positions follow the trapezoid rule where the velocity changed
///    smoothly, the end velocity where an impact or a stop changed it at
///    once (Integration.cpp);
///  - a slip that stops or turns round inside a part ends the part there
///    (SlipStops.cpp, SlipEvents.h).
class DynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  /// Bullet's world with its islands joined by contacts (ContactIslands).
  DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, btConstraintSolver* solver,
                btCollisionConfiguration* configuration);
  ~DynamicsWorld() override;

  /// The largest acceleration smooth forces (gravity, sliding friction)
  /// give a body, m/s^2: a velocity change beyond it times the step is an
  /// impact (0, the default: every contact is reused and no update is
  /// second order).
  void setSmoothAcceleration(double limit) { smoothAcceleration_ = limit; }
  /// Gravity becomes `g` m/s^2 along -Y for every body. The impulses the
  /// next solve starts from were found under the old gravity, and a
  /// resting load scales with it: they are scaled by new / old (dropped
  /// when the old was 0), so a resting body carries its new weight from
  /// the first step.
  void changeGravity(double g);
  double smoothAcceleration() const { return smoothAcceleration_; }
  /// A force (N) and torque (N m) on a body, world frame, through a step.
  struct Load {
    btRigidBody* body;
    btVector3 force;
    btVector3 torque;
  };
  /// What acts on bodies besides gravity through the next step(s), applied
  /// in every part where gravity is.
  void setLoads(std::vector<Load> loads);
  /// Solves independent islands on `threads` threads (the calling one
  /// included; 1: on it alone). The result is the same to the bit for any
  /// count (SolveIslands.cpp).
  void setThreads(int threads);
  /// Turns the second-order position update on (off by default).
  void setSecondOrderPositions(bool on) { secondOrder_ = on; }

  /// One step of `dt` seconds, no interpolation, in parts cut at impacts;
  /// carried impulses are scaled when a part's length differs from the
  /// part before.
  void step(double dt);

  /// A pair that struck inside the last step: `at` s after the step's
  /// start, a struck point's normal on B (from B towards A).
  struct Struck {
    const btCollisionObject* a;
    const btCollisionObject* b;
    btVector3 normalOnB;
    double at;
  };
  /// The pairs that bounced inside the last step, in time order: they may
  /// be apart again by its end, where the manifolds no longer show it.
  const std::vector<Struck>& struck() const { return struck_; }
  /// Steps whose events used up the parts a step may be cut into.
  long partBudgetSteps() const { return partBudgetSteps_; }
  /// Steps taken group by group: their groups without an event took the
  /// step whole, the others were taken again in parts (GroupSteps.cpp).
  long groupedSteps() const { return groupedSteps_; }
  /// Of those, steps taken again whole as one world, because a body
  /// taken again came to touch one that had taken the step whole.
  long regroupedSteps() const { return regroupedSteps_; }
  /// Parts taken so far, all told.
  long parts() const { return parts_; }
  /// Parts x bodies and parts x contact points so far (WorkCount.h).
  const WorkCount& work() const { return work_; }

  /// Bullet's narrow phase, with the impulses of points a compound dropped
  /// carried over (CarriedImpulses).
  void performDiscreteCollisionDetection() override;
  void countWork();  // this part's bodies and contact points, into work_

 private:
  // One part of the step: its place in the step and its length. `left` is
  // what remained of the step at the part's start, the length Bullet's
  // prediction, broadphase and deactivation see; `length` is where the
  // part ends, shortened at the first event found inside it.
  struct Part {
    int index = 0;
    double offset = 0.0;  // s from the step's start
    double left = 0.0;    // s
    double length = 0.0;  // s
    bool mayCut = false;  // the part may end at an event
    bool grouped = false; // its events are found group by group (GroupSteps.cpp)
  };
  // The parts of a step of `dt` s, the first found group by group if
  // `grouped` (Step.cpp).
  void takeParts(double dt, bool grouped);
  // The stages of a part, in order (Step.cpp).
  void stepPart(Part& part);
  // Stage 1: reads the velocities the part starts from, adds gravity to
  // the forces of the coming part, and applies the rolling resistance.
  void startPart(Part& part);
  // Stages 3-6: stale points dropped, touching impacts bounced, the part
  // cut at the next event, the islands solved.
  void solveContacts(Part& part, btContactSolverInfo& solverInfo);
  void dropStalePoints();
  // The earliest event inside the part (an impact, a pair with no point
  // closing fast, a face exit), the part's length if none; with
  // `eventful`, the bodies of every event inside it are added.
  double earliestEvent(const Part& part, const ImpactScan& scan, BodySet* eventful);
  void cutAtNextEvent(Part& part, const ImpactScan& scan);

  // Groups apart (GroupSteps.cpp). A step's first part finds its events
  // group by group (StepGroups): with none, or in every group, the step
  // goes on as one world; with events in some, the first part takes the
  // whole step for every group, and the groups with events are put back
  // to the step's start and taken again in parts while the rest are set
  // aside.
  enum class Grouping { kNone, kAll, kSome };
  // Also sets `cut` to the earliest event's time (earliestEvent).
  Grouping groupEvents(const Part& part, const ImpactScan& scan, double& cut);
  void saveStepStart();
  // What carries from part to part, back as it was at the step's start.
  void putBackCarried(double dt);
  void savePointsStart();
  void stepGroupsApart(double dt);
  // Puts the bodies of `only` (every body if null), or the points of their
  // manifolds, back as they were at the step's start.
  void putBackBodies(const BodySet* only);
  void putBackPoints(const BodySet* only);
  const BodySet* pointsBack_ = nullptr;  // the retaking part puts these points back
  bool putBackAll_ = false;              // ... or every point
  void setAside(const BodySet& calm);
  void bringBack();
  // Whether a pair of the broadphase joins a body taken again to one set
  // aside.
  bool crossesAside();
  bool slipCounts(const Slip& slip, double length, double g) const;

  // Stage 6's islands, each solved by Bullet's solver or, with tabletop's
  // and more than one thread, shared out among the threads, one
  // IslandSolver each (SolveIslands.cpp).
  void solveIslands(btContactSolverInfo& solverInfo);
  struct IslandJob {
    std::size_t firstBody;  // in islandBodies_
    int numBodies;
    btPersistentManifold** manifolds;
    int numManifolds;
  };
  std::vector<IslandJob> islandJobs_;    // this solve's, in Bullet's island order
  std::vector<IslandJob> kinematicJobs_; // those touching a kinematic body: on the calling thread
  std::vector<btCollisionObject*> islandBodies_;
  std::unique_ptr<WorkerThreads> threads_;
  std::vector<std::unique_ptr<IslandSolver>> helpers_;  // one a thread beyond the first

  StepGroups groups_;
  BodySet eventful_;  // bodies with an event in the first part
  BodySet retaken_;   // the bodies of their groups
  BodySet aside_;     // the rest, set aside while those are taken again
  bool split_ = false;    // the first part found events in some groups
  bool crossed_ = false;  // crossesAside() in a part taken again
  long groupedSteps_ = 0;
  long regroupedSteps_ = 0;
  struct BodyStart {
    btRigidBody* body;
    btTransform place;
    btVector3 linear, angular;
    btScalar deactivation;
    int activation;
  };
  std::vector<BodyStart> bodyStart_;
  struct ManifoldStart {
    btPersistentManifold* manifold;
    const btCollisionObject* a;
    const btCollisionObject* b;
    int count;
    btManifoldPoint points[MANIFOLD_CACHE_SIZE];
  };
  std::vector<ManifoldStart> manifoldStart_;  // in the dispatcher's order
  std::vector<std::pair<const btPersistentManifold*, std::size_t>> manifoldOrder_;  // by manifold: its index above
  // What carries from part to part, at the step's start.
  struct CarriedStart {
    BodySet settling[2];
    SlidingContacts sliding;
    std::vector<std::pair<btVector3, btVector3>> endVelocities;
  };
  CarriedStart carriedStart_;
  btAlignedObjectArray<btRigidBody*> allBodies_;  // while some are set aside
  std::vector<int> asideActivation_;
  // Stage 7: positions from the velocities (Integration.cpp); bodies
  // touching nothing turn as the free rigid body does (FreeFlight.h).
  void integrate(const Part& part);
  // integrate but for the free bodies' turn (freeFlight_).
  void integrateMotions(const Part& part);
  FreeFlight freeFlight_;

  void applyRollingResistance(const Part& part);
  // Each body's velocity and spin now, which the second-order update takes
  // as the part's start (startVelocities_, startSpins_).
  void saveStartVelocities();
  // The bodies whose velocities changed since the last part ended (a push,
  // a scene's start): kicked_.
  void noteKicked();

  bool markImpacts(double timeStep);
  void forgetImpacts();
  void resolveTouchingImpacts(const Part& part, btContactSolverInfo& solverInfo);
  // Records the pairs the impact solve just bounced (struck()).
  void noteStruck(const Part& part);
  // Clears every point's kBouncedFlag as the part ends.
  void forgetBounced();
  void scaleCarriedImpulses(double ratio);
  // Ends the part at `length` s instead: scales the impulses it carries
  // and gives back the rolling resistance of the time it lost.
  void shortenPart(Part& part, double length);
  // How a part is solved: whole; or ready to be cut where a slip turns
  // round (SlipEvents.h); or again, after such a cut.
  enum class PartSolve { kWhole, kMayCutAtSlip, kAfterSlipCut };
  SlipTurn solvePart(Part& part, btContactSolverInfo& solverInfo, const ImpactScan& scan, PartSolve how);
  // A part in which no body touches or nears another (free flight): solved
  // as Bullet solves it, leaving what solvePart leaves when there are no
  // contacts, without scanning for them.
  void solveUntouched(const Part& part, btContactSolverInfo& solverInfo);
  // What a solved part leaves for the next, solvePart's and solveUntouched's
  // alike: a solve has run, the bodies its closing points stopped, and the
  // slips that stopped in it (none of either for a part with no contacts).
  // Points closing at a part's start, with their manifolds.
  using ClosingPoints = std::vector<std::pair<const btPersistentManifold*, const btManifoldPoint*>>;
  void noteSolved(const ClosingPoints& closing, const std::vector<Slip>& slipping);
  std::vector<btManifoldPoint*> holdFrictionAlongLine();
  // After a part cut at a slip's turn and solved again: the line the slip
  // slid on, for the next part's friction rows, and whether it stopped.
  void noteSlipEnd(const Part& part, const SlipTurn& turned);
  void findSlipStops(const std::vector<Slip>& slipping);
  bool slidIn(const ContactKey& key) const;
  // Slips slower than this share of what kinetic friction removes in a
  // part are taken as stuck; friction this close to its limit as sliding.
  static constexpr double kSlipShare = 1e-3;
  // Points whose slips' directions have cosines above this with one
  // another slip along one line (within 2.6 degrees).
  static constexpr double kOneLine = 0.999;
  // The closing speed, m/s, above which a point that stops a body counts
  // as stopping it at once: a tenth of what smooth forces give in a step,
  // above a resting contact's rounding. A point closing just under it
  // moves by the body's mean velocity and can go this times dt / 2 in;
  // lower thresholds let the pyramid's sweeps drift
  // (docs/bullet-corrections.md, "Left").
  double stopSpeed() const { return 0.1 * smoothAcceleration_ * stepLength_; }

  // How many times the settings' iterations an island holding an impact
  // gets (IslandSolver::setImpactSweeps; every island with Bullet's own
  // solver).
  static constexpr int kImpactSweeps = 5;
  // At most this many parts to a step (the cap on impacts placed at their
  // own time in one step; past it the rest of the step is taken whole).
  static constexpr int kMaxParts = 8;
  double smoothAcceleration_ = 0.0;
  bool secondOrder_ = false;
  double lastStep_ = 0.0;    // the length of the part before, s (0: none yet)
  double stepLength_ = 0.0;  // the step being taken, s
  std::vector<Struck> struck_;
  long partBudgetSteps_ = 0;
  long parts_ = 0;
  bool solved_ = false;      // a solve has run: contacts carry their loads
  HeldGaps::Storage heldGaps_;
  HeldPlaces::Storage heldPlaces_;
  PointBoxes pointBoxes_;  // the boxes the part's points lie on (FaceExits)
  ImpactScan::Storage impactStorage_;  // the part's ImpactScan's
  BodySet stopped_;  // bodies a closing point stopped in the last solve
  // Adds to stopped_ the bodies resting on them whose touching points'
  // normal velocity the stop changed at once.
  void spreadStops();
  // spreadStops' scratch: each body's index among the moving ones and its
  // manifolds (by world array index), and the manifolds left to look at.
  struct StopSpread {
    std::vector<int> moving;
    std::vector<std::vector<int>> manifoldsOf;
    std::vector<int> work;
  };
  StopSpread stopSpread_;
  // A slip's share of the part (slipped for) and its contacts' normal, unit.
  struct SlipStop {
    double share = 1.0;
    btVector3 normal{0, 0, 0};
  };
  // What a body's slips did in the last solve's part (findSlipStops, read
  // by integrateTransforms):
  // - stop: the first of its contacts whose slip friction stopped inside
  //   the part (share below 1; 1: none stopped), and the friction there
  //   that took back its rolling resistance's slip (stopTaken, N s over
  //   the part: after the stop, it is the friction that still acts);
  // - face: the face (three points or more carrying load) with the largest
  //   friction limit it slipped on (faceLimit, N s; 0: none), about whose
  //   normal only that friction turns the body.
  struct BodySlip {
    SlipStop stop;
    double stopTaken = 0;
    SlipStop face;
    double faceLimit = 0;
  };
  std::unordered_map<const btCollisionObject*, BodySlip> slips_;
  BodySet settling_[2];  // the bodies whose slip stopped in a part, and in the one before
  SlidingContacts sliding_;  // contacts whose friction was at its limit in it
  SlidingContacts slidingNext_;  // findSlipStops', kept to reuse its storage
  // A contact's friction in the last solve, its limit, and its points'
  // normals by their loads, turned one way (findSlipStops; kept to reuse
  // its storage).
  struct SlipUse {
    const btPersistentManifold* manifold;
    double friction = 0, limit = 0;
    btVector3 normal{0, 0, 0};
    int loaded = 0;  // slipping points carrying load
  };
  std::vector<std::pair<ContactKey, SlipUse>> slipUse_;
  std::vector<std::pair<ContactKey, std::size_t>> slipOrder_;  // slipping's points by contact
  std::vector<std::pair<btVector3, btVector3>> endVelocities_;  // each body's at the last part's end
  BodySet kicked_;  // noteKicked's
  std::vector<btVector3> startVelocities_;
  std::vector<btVector3> startSpins_;    // rad/s, read with startVelocities_
  std::vector<btTransform> startPoses_;  // each body's at the part's start
  BodySet meanTurn_;  // bodies with rows held at the mean
  RollingLines rolling_;  // bodies rolling on a line that turns
  KeptOut keptOut_;       // points the integration keeps out of fixed supports
  BodySet rolled_;        // those whose velocity it turned this part
  std::vector<std::pair<btRigidBody*, int>> rollingFlags_;  // and their own flags
  void carryRolling();    // turns their velocity (RollingLines::transport)
  // solvePart's, kept to reuse their storage: the impulses a part carries
  // on, the points closing at its start and their bodies.
  std::vector<std::pair<btManifoldPoint*, btVector3>> partCarried_;
  ClosingPoints closing_;
  std::vector<Slip> slipping_;  // the points slipping at its start
  std::vector<Slip> mayTurn_;   // those whose slip may turn in it
  BodySet stopping_;
  BodySet touchingAnother_;  // slipsThatMayTurn's scratch
  std::vector<Load> loads_;  // setLoads()
  CarriedImpulses carried_;  // per non-static body, at the step's start
  PartStart partStart_;      // the part's start, while a slip may turn in it
  // The contact whose slip turned round or stopped where the last part was
  // cut, the line it slid on, and whether it turned round.
  struct SlipEnd {
    ContactKey contact;
    btVector3 along;
    bool reversed;
  };
  std::optional<SlipEnd> lastSlipEnd_;
  std::optional<SlipEnd> slipEndStart_;  // lastSlipEnd_ at the step's start (GroupSteps.cpp)
  std::vector<std::pair<btRigidBody*, btVector3>> resisted_;  // the part's rolling-resistance impulses, N m s
  // Each resisted contact's part (applyRollingResistance): the friction
  // impulse that takes back the slip the resistance made (N s, over the
  // whole part), and whether it slipped before the resistance acted.
  struct ResistedSlip {
    ContactKey contact;
    double friction = 0;
    bool slippedBefore = false;
  };
  std::vector<ResistedSlip> resistedSlips_;
  std::vector<std::size_t> resistedOrder_;  // resistedSlips_' indices by contact
  BodySet resistedBodies_;                   // the bodies of resisted_
  const ResistedSlip* resistedSlip(const ContactKey& key) const;  // the contact's, or null
  ContactIslands islands_;   // replaces the island manager Bullet made
  WorkCount work_;
  IslandSolver* islandSolver_;  // the constraint solver, if tabletop's (else null)
};

}  // namespace tabletop
