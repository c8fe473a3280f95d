#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Arrow.h"
#include "core/BodyMotion.h"
#include "core/ContactReport.h"
#include "core/ContactSolver.h"
#include "core/EntityState.h"
#include "core/Event.h"
#include "core/Vec3.h"
#include "core/WorkCount.h"

namespace tabletop {

/// One scene in one mode (bullet, compat or rules). The script runner, the
/// viewer and the benchmarks drive every mode through this interface.
class Simulation {
 public:
  virtual ~Simulation() = default;

  /// The mode's name as printed ("bullet", ...).
  virtual std::string_view modeName() const = 0;
  /// Applies a push now. Throws std::invalid_argument if the mode cannot.
  virtual void push(const Arrow& arrow, const PushMagnitude& magnitude) = 0;
  /// Turns an entity about its own vertical axis by `degrees` (report 4).
  virtual void rotate(const std::string& entity, double degrees) = 0;
  /// Advances one fixed timestep.
  virtual void step() = 0;
  /// Simulated seconds so far.
  virtual double time() const = 0;
  /// Steps taken so far.
  virtual long steps() const = 0;
  /// True when no entity moves.
  virtual bool allAtRest() const = 0;
  /// Every entity's state, in scenario order.
  virtual std::vector<EntityState> snapshot() const = 0;
  /// Every entity's motion, in scenario order: what snapshot() says of
  /// it, cheaper, for checks made after every step.
  virtual std::vector<BodyMotion> motions() const {
    std::vector<BodyMotion> out;
    for (const EntityState& s : snapshot()) {
      out.push_back({s.position, s.orientation, s.linearVelocity, s.angularVelocity});
    }
    return out;
  }
  /// Everything that happened so far, in time order.
  virtual const std::vector<Event>& events() const = 0;
  /// Applies an impulse of `impulse` N s now, through the entity's centre
  /// of mass or, when `point` is given, at that point (m, world frame), so
  /// that it also sets the body spinning. Modes that follow the report's
  /// rules take only a horizontal push through the centre (report 3.5), as
  /// push() by impulse; anything else throws std::invalid_argument.
  virtual void applyImpulse(const std::string& entity, const Vec3& impulse, const std::optional<Vec3>& point);
  /// Applies `force` N and `torque` N m to an entity through the next step
  /// only (as PyBullet's applyExternalForce): the force through the centre
  /// of mass or, when `point` is given (m, world frame), at that point,
  /// which adds its moment (r x F, r taken now). Modes that follow the
  /// report's rules move bodies by pushes alone: they throw
  /// std::invalid_argument.
  virtual void applyForce(const std::string& entity, const Vec3& force, const Vec3& torque,
                          const std::optional<Vec3>& point);
  /// Steps from now on last `seconds` (a checked timestep, ValueRanges.h).
  virtual void setTimestep(double seconds) = 0;
  /// Gravity from now on: `g` m/s^2 along -Y (checked, ValueRanges.h).
  virtual void setGravity(double g) = 0;
  /// The points where bodies touch after the last step, within 1 mm of
  /// touching (none in modes without contacts).
  virtual std::vector<ContactReport> contacts() const { return {}; }
  /// Where bodies touch now, m, for drawing: contacts()' points.
  std::vector<Vec3> contactPoints() const;
  /// How the contact solver solved the islands so far (none in the rules).
  virtual SolverUse solverUse() const { return {}; }
  /// The work done so far (WorkCount.h); ScriptPlayer bounds a run by it.
  virtual WorkCount work() const { return {}; }
};

}  // namespace tabletop
