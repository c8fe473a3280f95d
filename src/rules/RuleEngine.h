#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/Settings.h"
#include "core/Simulation.h"
#include "core/StepClock.h"
#include "core/TableSpec.h"
#include "rules/ContactFinder.h"
#include "rules/ReportRules.h"
#include "rules/RuleBody.h"

namespace tabletop::rules {

/// Takes over a body that passes a table edge (the compat mode hands it to
/// full physics). Without one, the engine drops it by the rules.
class ReleaseHandler {
 public:
  virtual ~ReleaseHandler() = default;
  /// `body` leaves the rules at its current place, moving at `velocity` m/s.
  virtual void release(std::size_t body, const Vec3& velocity) = 0;
};

/// The report's algorithm as a kinematic simulator (mode "rules"; the
/// compat mode drives Bullet bodies with it).
///
/// - A push of `step` metres moves its entity that far in a straight line
///   along the push (report 3.8), at a constant kDriveSpeed: the report
///   animates a push over frames; the speed sets only the timing.
/// - An entity resting on another is carried with it (report 3.7).
/// - A body struck by a moving one (ContactFinder) receives the push at its
///   centre in the same direction, and both move the same remaining
///   distance: the straight-line transfer (report 3.7). Chains pass on.
/// - A sphere striking a sphere (report 3.7, "different trajectories"): with
///   D the striker's remaining step and theta the angle between its
///   direction and the line of centres n at contact, the struck sphere rolls
///   Step1 = D cos^2(theta) along n and the striker Step2 = min(D sin^2(theta),
///   Step1) along the rest of its direction (u - (u.n) n). This is where two
///   equal frictionless spheres, both slowing at the same rate, would go
///   after an elastic collision, capped so that Step1 >= Step2 as the report
///   requires.
/// - A table-supported entity whose centre reaches a table edge stops being
///   pushed: status DropFrom...Edge (report 3.4) for it and what it carries.
///   It moves on along its direction until its footprint clears the edge,
///   then falls straight down under gravity and lands on the first top it
///   meets whose footprint holds its centre (report 3.4, 3.8): the table,
///   the ground, or a body, resting or falling too; found as the fall
///   goes (landing()). Landing on the ground, or on what stays up, ends
///   the drop (FinishDropSimulation).
/// - An entity that never was on the table (on the ground, on a stack
///   there, or in the air beside the table) is OnGround while it rests and
///   OffTable while it falls (EntityPositionStatus.h). It may be pushed
///   when it rests on another entity; pushed off that one it clears its
///   edge and falls like a rider, whatever table edge its centre passes.
/// - A pushed entity resting on another slides across it until its centre
///   passes the lower one's edge; it then clears that edge the same way and
///   falls onto what is below (the table, or the ground past a table edge).
///
/// Entities that fall no longer strike others. Pushes are given as steps;
/// a push on an entity on the ground, dropping, or still moving from an
/// earlier push throws std::invalid_argument.
class RuleEngine : public Simulation {
 public:
  /// Metres per second at which pushes move entities.
  static constexpr double kDriveSpeed = 0.5;

  RuleEngine(std::string mode, const Settings& settings, const TableSpec& table, std::vector<RuleBody> bodies,
             std::unique_ptr<ContactFinder> finder, ReleaseHandler* release = nullptr);

  const std::vector<RuleBody>& bodies() const { return bodies_; }
  const TableEdges& edges() const { return edges_; }
  /// True once a body was handed to the ReleaseHandler.
  bool released(std::size_t i) const { return motion_[i].phase == Phase::Released; }
  /// Current velocity of a body the engine moves, m/s.
  Vec3 velocity(std::size_t i) const;

  // Simulation
  std::string_view modeName() const override { return mode_; }
  void push(const Arrow& arrow, const PushMagnitude& magnitude) override;
  void rotate(const std::string& entity, double degrees) override;
  void step() override;
  void setTimestep(double seconds) override;
  void setGravity(double g) override { settings_.gravity = g; }
  double time() const override { return time_; }
  long steps() const override { return steps_; }
  bool allAtRest() const override;
  std::vector<EntityState> snapshot() const override;
  const std::vector<Event>& events() const override { return events_; }
  WorkCount work() const override { return work_; }

 private:
  enum class Phase {
    Resting,   // on a surface; moves only with what carries it
    Driven,    // on a surface, moving along `direction` for `remaining` m
    Clearing,  // past an edge, moving on until its footprint clears it
    Falling,   // straight down under gravity until it meets a top (landing())
    Released,  // handed to the ReleaseHandler
  };
  struct Motion {
    Phase phase = Phase::Resting;
    Vec3 direction;          // unit, horizontal
    double remaining = 0.0;  // m, along direction
    double fallSpeed = 0.0;  // m/s, downwards
    bool moving = false;     // moved in the last advance (for at-rest events)
  };
  // What stops the current advance.
  struct Next {
    enum class Kind { None, DriveEnds, Strike, TableEdge, BaseEdge, Lands };
    Kind kind = Kind::None;
    double t = 0.0;  // s from now
    std::size_t body = 0;
    std::size_t other = 0;
    Vec3 normal;
    EntityPositionStatus edge = EntityPositionStatus::OnTable;  // TableEdge: which
    int on = kOnGround;  // Lands: kOnTable, kOnGround or a body index
    double top = 0.0;    // Lands: the height of that top now, m (to break ties)
    double checks = 0.0; // bodies and pairs looked at to find it (WorkCount)
  };

  // Bodies whose vertical extents overlap by less than this do not meet
  // sideways: one rests on the other.
  static constexpr double kLevelSlack = 1e-6;  // m

  std::size_t index(const std::string& name) const;
  bool onSurface(std::size_t i) const;
  bool moving(std::size_t i) const;
  Vec3 ownVelocity(std::size_t i) const;
  Next nextEvent(double horizon) const;
  Next nextStrike(Next best) const;  // the first strike before best.t, else best
  std::vector<Vec3> velocities() const;  // velocity(i) for every body at once
  // Pairs (i < j, ascending) of a mover and a surface body that may meet
  // within `horizon` s at velocities `v`.
  std::vector<std::pair<std::size_t, std::size_t>> pairsNear(const std::vector<std::size_t>& movers,
                                                             const std::vector<Vec3>& v, double horizon) const;
  void advance(double dt);
  void handle(const Next& next);
  void strike(std::size_t striker, std::size_t struck, const Vec3& normal);
  std::size_t driver(std::size_t i) const;
  void leaveTable(std::size_t i, EntityPositionStatus status);
  void startClearing(std::size_t i, const Vec3& outward);
  void startFall(std::size_t i);
  Next landing(std::size_t i) const;
  bool descends(std::size_t i) const;  // falling, or carried by a falling body
  int heldBy(std::size_t i) const;     // its support followed down: kOnTable, kOnGround or kOnNothing
  void judgeStatus(std::size_t i);     // the status rule, with down = landed on what stays up
  void land(std::size_t i, int on);
  std::vector<std::size_t> riders(std::size_t i) const;
  Support supportOf(int support) const;  // a RuleBody's support as a value
  void noteRest();
  Event eventNow(EventType type, const std::string& entity) const;  // at now_
  void record(Event e);

  std::string mode_;
  Settings settings_;
  double tableTop_;
  TableEdges edges_;
  std::vector<RuleBody> bodies_;
  std::vector<Motion> motion_;
  std::vector<Vec3> own_;  // scratch for advance(), kept between steps
  std::unique_ptr<ContactFinder> finder_;
  ReleaseHandler* release_;
  std::vector<Event> events_;
  WorkCount work_;
  double time_ = 0.0;  // at the start of the current step
  double now_ = 0.0;   // within the current step, for events
  long steps_ = 0;
  StepClock clock_;
};

}  // namespace tabletop::rules
