#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "core/Settings.h"
#include "core/TableSpec.h"
#include "physics/World.h"

namespace tabletop::test {

/// Standard gravity used by every analytic prediction, m/s^2.
inline constexpr double kG = 9.81;

/// A table-top world for physics tests, after Jolt's PhysicsTestContext:
/// makeTable() builds the scene, simulate(seconds) steps it, and the tests
/// compare what happens with closed forms.
class PhysicsFixture : public ::testing::Test {
 protected:
  /// A world with the default table (1.2 m x 0.8 m, top at 0.75 m).
  World& makeTable(double timestep = 1.0 / 240.0, const TableSpec& table = TableSpec{}) {
    Settings s;
    s.timestep = timestep;
    s.gravity = kG;
    world_ = std::make_unique<World>(s, table);
    return *world_;
  }

  /// Steps the world for `seconds` of simulated time.
  void simulate(double seconds) {
    const long steps = static_cast<long>(seconds / world_->settings().timestep + 0.5);
    for (long i = 0; i < steps; ++i) world_->step();
  }

  /// Steps until every entity is at rest, or `limit` seconds pass.
  void simulateUntilRest(double limit) {
    const double end = world_->time() + limit;
    do {
      world_->step();
    } while (!world_->allAtRest() && world_->time() < end);
  }

  World& world() { return *world_; }

 private:
  std::unique_ptr<World> world_;
};

}  // namespace tabletop::test
