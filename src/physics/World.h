#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "core/Settings.h"
#include "core/Simulation.h"
#include "core/StepClock.h"
#include "core/TableSpec.h"
#include "physics/step/DynamicsWorld.h"
#include "physics/shapes/Ground.h"
#include "physics/Pipeline.h"
#include "physics/shapes/Shape.h"
#include "physics/shapes/Table.h"

namespace tabletop {

/// A vector between tabletop's plain type and Bullet's.
inline btVector3 toBullet(const Vec3& v) { return btVector3(v.x, v.y, v.z); }
inline Vec3 toVec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

/// A scene in full Bullet physics (mode "bullet"): owns the Bullet pipeline,
/// the Table, the Ground and the entities, and steps them at a fixed rate,
/// each step cut into equal parts while a body moves fast for its size
/// near something it could strike (substeps()).
///
/// After every step it updates each entity's report status (3.4), its
/// support, and whether it is at rest, and records the events: contacts
/// beginning between entities, an entity leaving the table, landing on a
/// new support, coming to rest.
///
/// Deterministic: no interpolation, no randomised solver order, sorted
/// overlapping pairs, islands that give the same answer on any thread
/// (Settings::threads); the same scene and settings give bit-identical
/// states.
class World : public Simulation {
 public:
  World(const Settings& settings, const TableSpec& table, const Material& ground = kNeutralMaterial);
  ~World() override;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds an entity of `mass` kg with its centre at `centre`, turned by
  /// `yawDegrees` about +Y. Entities keep the order they were added in.
  Shape& addEntity(std::unique_ptr<Shape> shape, double mass, const Material& material,
                   const btVector3& centre, double yawDegrees);
  /// The same, turned by `orientation` (body to world).
  Shape& addEntity(std::unique_ptr<Shape> shape, double mass, const Material& material,
                   const btVector3& centre, const btQuaternion& orientation);

  const Settings& settings() const { return settings_; }
  const Table& table() const { return table_; }
  /// Whether the table's legs take part in collisions yet (always, unless
  /// Settings::legsWhenReachable keeps them out until a body can reach them).
  bool legsInWorld() const { return legsIn_ || !settings_.bullet.legsWhenReachable; }
  const std::vector<std::unique_ptr<Shape>>& entities() const { return entities_; }
  /// The entity called `name`, or null.
  Shape* find(std::string_view name);

  /// Pairs of bodies ("table" for the table) that interpenetrate by more
  /// than `tolerance` metres in the current state.
  std::vector<std::pair<Support, Support>> overlaps(double tolerance);
  /// How deep the deepest contact of the last step is, metres (0 if none
  /// penetrates).
  double deepestPenetration() const;

  /// Makes entity `i` kinematic: it keeps still, or goes where
  /// placeKinematic() puts it, and pushes dynamic bodies out of its way
  /// (the compat mode drives entities on the table this way).
  void makeKinematic(std::size_t i);
  /// Puts kinematic entity `i` with its centre at `centre`, turned by
  /// `yawDegrees`; Bullet takes its velocity from the move.
  void placeKinematic(std::size_t i, const btVector3& centre, double yawDegrees);
  /// Makes kinematic entity `i` dynamic again, moving at `velocity` m/s.
  void makeDynamic(std::size_t i, const btVector3& velocity);
  /// Looks at the scene as it stands, on the contacts the last collision
  /// detection found (overlaps() finds them): what holds each entity up and
  /// its status, on the table or never on it. Bookkeeping only, so a
  /// snapshot before the first step shows them; the first step(), push()
  /// or rotate() looks again.
  void look() { observe(false); }
  /// True once entity `i` has been slow for the rest window (see observe()).
  bool atRest(std::size_t i) const { return trackers_.at(i).atRest; }

  /// The impulse (N*s, along the arrow) a push of `magnitude` gives.
  double pushImpulse(const Arrow& arrow, const PushMagnitude& magnitude);
  /// How many equal parts the next step is cut into at the entities'
  /// present velocities (see World.cpp).
  int substeps() const;

  // Simulation
  std::string_view modeName() const override { return "bullet"; }
  void push(const Arrow& arrow, const PushMagnitude& magnitude) override;
  void rotate(const std::string& entity, double degrees) override;
  void step() override;
  void applyForce(const std::string& entity, const Vec3& force, const Vec3& torque,
                  const std::optional<Vec3>& point) override;
  void setTimestep(double seconds) override;
  void setGravity(double g) override;
  double time() const override { return time_; }
  long steps() const override { return steps_; }
  bool allAtRest() const override;
  std::vector<EntityState> snapshot() const override;
  std::vector<BodyMotion> motions() const override;
  const std::vector<Event>& events() const override { return events_; }
  void applyImpulse(const std::string& entity, const Vec3& impulse, const std::optional<Vec3>& point) override;
  std::vector<ContactReport> contacts() const override;
  SolverUse solverUse() const override;
  WorkCount work() const override;

 private:
  // A support index that names no body.
  static constexpr int kNoSupport = -100;
  // An entity is at rest once slower than these for kRestWindow seconds
  // (observe(); Bullet's sleeping thresholds too).
  static constexpr double kRestSpeed = 5e-3;   // m/s
  static constexpr double kRestSpin = 5e-2;    // rad/s
  static constexpr double kRestWindow = 0.1;   // s

  // Per-entity bookkeeping that is not the report's.
  struct Tracker {
    int support = kNoSupport;      // user index of the current support
    int lastSupport = kNoSupport;  // the last support that was not none
    double quietSince = -1.0;  // when the entity last became slow, or -1
    bool atRest = true;
    double inner = 0.0;  // the smallest half extent, m
    double turningReach = 0.0;  // how far its surface moves per radian turned, m
    btVector3 lastCentre{0, 0, 0};    // at the start of the step, m
    btVector3 lastVelocity{0, 0, 0};  // at the start of the step, m/s
  };

  Shape& entity(const std::string& name);
  void start();
  void updateSmoothAcceleration();
  // Hands the step the loads applyForce() gave, widening the bound on
  // smooth accelerations by the largest they add.
  void takeLoads();
  void addLegsIfReachable();
  // The observer (WorldObserver.cpp), after each step: the contacts, the
  // pairs touching, each entity's support, edge and rest.
  void observe(bool emit);
  void gatherContacts();
  void observeTouching(bool emit);
  void findSupports();
  void observeSupport(std::size_t i, bool emit);
  void observeEdge(std::size_t i, bool emit);
  void observeRest(std::size_t i, bool emit);
  /// What holds entity `i` up after the last look, followed down through
  /// the entities under it: the table, the ground, or nothing.
  Support::Kind heldBy(std::size_t i) const;
  /// When, inside the step just taken, entity `shape` falling freely from
  /// its start (tracker) reached the height at which it rests flat on
  /// `support` (a user index): a landing's own time, not the step's end.
  double landingTime(const Tracker& tracker, const Shape& shape, int support) const;
  /// When, in the step just taken, entities `entity` and `other` (user
  /// indices) first struck each other; none if they did not.
  std::optional<double> firstStruck(int entity, int other) const;
  // Sorts struck_ into struckTimes_ for firstStruck, once per look.
  void sortStruck();
  struct StruckTime {
    std::pair<int, int> pair;  // user indices, the lower first
    double at;                 // s after the step's start
  };
  std::vector<StruckTime> struckTimes_;  // sortStruck's
  void record(const Event& e);
  // A push of `impulse` N s given to `shape` now: it wakes, and the event says so.
  void recordPush(Shape& shape, Event e);
  Support participant(const btCollisionObject* object) const;
  Support participant(int userIndex) const;

  // One body touching an entity, as observe() gathers them.
  struct Contact {
    int entity;       // index of the entity
    int other;        // user index of the other body
    double distance;  // closest point, m (negative: penetration)
    double support;   // upward normal impulse, N*s; -1 if it does not hold the entity up
  };
  // The pairs that struck inside the step (DynamicsWorld::struck), their
  // times from the step's start, over all its parts.
  std::vector<DynamicsWorld::Struck> struck_;

  Settings settings_;
  Pipeline pipeline_;
  btCollisionDispatcher* dispatcher_;  // pipeline_'s
  DynamicsWorld* world_;               // pipeline_'s
  Table table_;
  Ground ground_;
  std::vector<std::unique_ptr<Shape>> entities_;
  std::unordered_map<std::string, std::size_t> indexOf_;  // entity name -> index (the first of a name)
  std::vector<Tracker> trackers_;
  // The entity pairs touching after the last step, sorted; and scratch
  // kept to avoid reallocating: the contacts, the pairs touching now, each
  // entity's support, the impulse it gives and the one its support before
  // gives.
  std::vector<std::pair<int, int>> touching_;
  std::vector<Contact> contacts_;
  std::vector<Contact> byEntity_;          // gatherContacts' scratch
  std::vector<std::size_t> contactEnds_;  // gatherContacts' scratch: where each entity's entries end
  std::vector<std::pair<int, int>> touchingNow_;
  std::vector<int> supports_;
  std::vector<double> strongest_;
  std::vector<double> currentPush_;
  std::vector<Event> events_;
  // The forces and torques applied through the next step (applyForce()).
  std::vector<DynamicsWorld::Load> loads_;
  double entityFriction_ = 0.0;  // the largest friction coefficient of any entity
  double time_ = 0.0;
  long steps_ = 0;
  StepClock clock_;
  bool started_ = false;
  bool legsIn_ = false;  // the table's separate legs are in the world
};

}  // namespace tabletop
