#pragma once

#include <memory>
#include <vector>

#include "core/Simulation.h"
#include "physics/World.h"
#include "rules/RuleEngine.h"

namespace tabletop {

/// Mode "compat": Bullet bodies constrained to the report's rules.
///
/// Every entity on the table is a kinematic Bullet body: it does not turn,
/// and moves only where the rule engine drives it, in straight lines along
/// pushes; it is carried by what it rests on. When and where a moving body
/// strikes another is Bullet's answer (GJK distances, GjkContactFinder),
/// and the struck body takes the push through its centre in the same
/// direction, over the same distance. Once an entity's centre passes a
/// table edge it is released: it becomes a dynamic body again, with the
/// velocity it had, and falls under full physics to the ground; its drop
/// ends (FinishDropSimulation) once it has landed there: held up by the
/// ground, or by a released body whose drop has ended, and still
/// vertically for 0.1 s. (A ball may then roll on along
/// the floor; the rules have no floor to roll on.) A rider pushed off its base falls by the rules (the report's
/// straight drop onto the table); only table edges hand bodies to physics.
class CompatWorld : public Simulation, private rules::ReleaseHandler {
 public:
  CompatWorld(std::unique_ptr<World> world, std::vector<rules::RuleBody> bodies);

  World& world() { return *world_; }

  std::string_view modeName() const override { return "compat"; }
  void push(const Arrow& arrow, const PushMagnitude& magnitude) override;
  void rotate(const std::string& entity, double degrees) override;
  void step() override;
  void setTimestep(double seconds) override;
  void setGravity(double g) override;
  double time() const override { return engine_->time(); }
  long steps() const override { return engine_->steps(); }
  bool allAtRest() const override;
  std::vector<EntityState> snapshot() const override;
  const std::vector<Event>& events() const override { return events_; }
  std::vector<ContactReport> contacts() const override { return world_->contacts(); }
  SolverUse solverUse() const override { return world_->solverUse(); }
  WorkCount work() const override;

 private:
  void release(std::size_t body, const Vec3& velocity) override;
  void place();
  void observeReleased();
  void mergeEvents();

  std::unique_ptr<World> world_;
  std::unique_ptr<rules::RuleEngine> engine_;
  std::vector<bool> settled_;          // released and landed
  std::vector<double> landedSince_;    // when it last touched down still, or -1
  std::vector<Event> ownEvents_;       // landings of released bodies
  std::vector<Event> events_;    // engine's and own, in time order
};

}  // namespace tabletop
