#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/BodyMotion.h"
#include "core/Settings.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// A run stopped because its state stopped meaning anything: a quantity
/// became non-finite or exceeded what the scene's energy allows.
class DivergenceError : public std::runtime_error {
 public:
  DivergenceError(std::string entity, double time, std::string quantity, const std::string& detail);

  const std::string& entity() const { return entity_; }
  double time() const { return time_; }                   ///< simulated seconds
  const std::string& quantity() const { return quantity_; }  ///< "position", "speed", ...

 private:
  std::string entity_;
  double time_;
  std::string quantity_;
};

/// Checks every body after each step against bounds that follow from the
/// scene, not from tuning:
///  - position, orientation and velocities are finite, and the centre
///    stays within kWorldRadius of the origin and above the floor by more
///    than minus the body's bounding radius (a centre further down has
///    passed through the floor), and not inside the table top;
///  - speed |v| <= kSafety * sqrt(2 E / m_min) + kSlack, and angular speed
///    |w| <= kSafety * sqrt(5) * sqrt(2 E / m_min) / r_min + kSlack / r_min,
///    where E is an upper bound on the scene's mechanical energy (the
///    potential energy of every body above the floor at the start, plus the
///    kinetic energy at the start and what each push adds, its rotational
///    part bounded by m R^2 w^2 / 2 with R the bounding radius, as no
///    moment of inertia exceeds m R^2), m_min the lightest body and r_min
///    the smallest half-dimension of any body. No body can hold more than
///    all of E; every body's inertia about any axis is at least
///    0.2 m r_min^2 (a solid sphere's 2/5 m r^2 is the least of the shapes,
///    a thin box's or cylinder's smallest dimension is 2 r_min), hence the
///    angular bound. kSafety covers Bullet's penetration recovery, which
///    may add a little energy; a solver blowing up exceeds it by orders
///    of magnitude.
/// The bounds hold in every mode: the rule engine's kinematic speeds are
/// measured after each push like Bullet's.
class DivergenceGuard {
 public:
  static constexpr double kSafety = 2.0;
  static constexpr double kSlack = 0.5;          ///< m/s: a body dropped while a push is set up
  static constexpr double kWorldRadius = 1e5;   ///< m: ten times the largest accepted coordinate

  /// `start`: every entity's motion at the start, in scenario order (as
  /// every argument below).
  DivergenceGuard(const Scenario& scenario, const Settings& settings, const std::vector<BodyMotion>& start);

  /// Records the energy a push gave: the states just before and just
  /// after it.
  void pushed(const std::vector<BodyMotion>& before, const std::vector<BodyMotion>& after);
  /// Throws DivergenceError naming the first body out of bounds.
  void check(const std::vector<BodyMotion>& states, double time) const;

  double energyBound() const { return energy_; }  ///< J
  double speedBound() const;                       ///< m/s
  double angularSpeedBound() const;                ///< rad/s

 private:
  double kineticEnergy(const std::vector<BodyMotion>& states) const;

  TableSpec table_;
  std::vector<std::string> names_;  ///< in scenario order
  std::vector<double> masses_;  ///< kg, in scenario order
  std::vector<double> radii_;   ///< m, bounding radius of each body
  double lightest_ = 1.0;       ///< kg
  double smallest_ = 1.0;       ///< m, half the smallest dimension
  double energy_ = 0.0;         ///< J
};

}  // namespace tabletop
