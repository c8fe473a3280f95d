// A cube carrying a rider (a cube, a box, a cylinder or a truncated cone
// standing on its base), the cube pushed: the rider slips back on
// it until both move at one speed, then rides along (mu1 <= mu2) or slips
// on forwards as the support brakes the lower cube harder than the
// rider's friction can follow (mu1 > mu2). Every phase ends inside a step,
// where a slip stops or turns round (physics/SlipEvents.h). Each cube's
// travel against the closed form, over riders, masses, frictions,
// supports, directions and rates: within 0.1 mm from 60 Hz up, growing at second
// order below (0.4 mm at 30 Hz), as for sliding (SlideTest).
//
// Directions: along the table's axes both ways, and off them (37 and 233
// degrees), where a rider that slips on forwards after its slip stopped
// missed by 0.9 mm at 30 Hz and 0.15 mm at 60 Hz while the pivoted solve
// laid its friction rows along the world's axes (step/SlipStops.cpp).

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenes/LawScenes.h"
#include "physics/World.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;  // m/s^2

struct Travel {
  double a, b;  // m, each cube's from its start
};

// Phase 1 (0 to t1): A brakes at (mu2 mB + mu1 (mA + mB)) g / mA, B
// speeds up at mu2 g, until both move at v1. Phase 2: together at mu1 g;
// or, with mu1 > mu2, A at (mu1 (mA + mB) - mu2 mB) g / mA and B at mu2 g,
// each to rest (the support then holds A against B's friction).
Travel closedForm(const RideCase& c) {
  const double aB = c.mu2 * kG, aA = -(c.mu2 * c.massB + c.mu1 * (c.massA + c.massB)) * kG / c.massA;
  const double t1 = c.speed / (aB - aA), v1 = aB * t1;
  Travel d{c.speed * t1 + 0.5 * aA * t1 * t1, 0.5 * aB * t1 * t1};
  const double brakeA = c.mu1 <= c.mu2 ? c.mu1 * kG : (c.mu1 * (c.massA + c.massB) - c.mu2 * c.massB) * kG / c.massA;
  const double brakeB = c.mu1 <= c.mu2 ? c.mu1 * kG : c.mu2 * kG;
  d.a += v1 * v1 / (2.0 * brakeA);
  d.b += v1 * v1 / (2.0 * brakeB);
  return d;
}

Travel simulate(const RideCase& c) {
  const Scenario s = rideScene(c);
  const RunResult r = test::runScene(s);
  EXPECT_TRUE(r.complete) << describe(c);
  const auto travel = [&](std::size_t i) {
    const EntitySpec& e = s.entities[i];
    return std::hypot(r.entities[i].position.x - e.position.x, r.entities[i].position.z - e.position.z);
  };
  return {travel(0), travel(1)};
}

TEST(Ride, TheCubeAndItsRiderTravelTheClosedFormDistances) {
  struct Rider {
    const char* shape;
    const char* size;
  };
  struct Masses {
    double a, b;
  };
  struct Frictions {
    double mu1, mu2;
  };
  const Rider riders[] = {
      {"cube", "0.1"}, {"box", "[0.12, 0.04, 0.08]"}, {"cylinder", "[0.04, 0.04, 0.08]"}, {"cylinder", "[0.05, 0.03, 0.06]"}};
  for (const Rider& rider : riders) {
    for (const char* support : {"table", "ground"}) {
      for (const Masses m : {Masses{2.0, 0.5}, Masses{0.8, 1.2}}) {
        for (const Frictions f : {Frictions{0.6, 0.3}, Frictions{0.2, 0.5}}) {
          for (const double angle : {0.0, 37.0, 90.0, 180.0, 233.0}) {
            for (const double rate : {30.0, 60.0, 240.0, 1000.0}) {
              RideCase c{support, m.a, m.b};
              c.shapeB = rider.shape, c.sizeB = rider.size;
              c.mu1 = f.mu1, c.mu2 = f.mu2, c.angle = angle, c.rate = rate;
              const Travel expected = closedForm(c), got = simulate(c);
              const double tolerance = 1e-4 * std::max(1.0, std::pow(60.0 / rate, 2));
              EXPECT_NEAR(got.a, expected.a, tolerance) << "A, " << describe(c);
              EXPECT_NEAR(got.b, expected.b, tolerance) << "B, " << describe(c);
            }
          }
        }
      }
    }
  }
}

// Cubes resting on the support, each in an island of its own, keep their height
// while elsewhere a rider's slip turns round and its part is solved again:
// the second solve once scrambled Bullet's islands, and every body went
// unsupported for the part (resting bodies fell 0.9 mm, then rose).
TEST(Ride, ABodyElsewhereRestsThroughASlipCut) {
  for (const char* support : {"table", "ground"}) {
    for (const double rate : {30.0, 60.0, 240.0}) {
      RideCase c{support};
      c.rate = rate;
      Scenario s = rideScene(c);
      // Three cubes resting apart, each an island: one before the pair, one
      // between the cube and its rider (islands of bodies not listed one
      // after the other are the ones a second pass scrambled), one after.
      const EntitySpec cube = s.entities.at(0);
      const auto restingAt = [&](double dz, std::size_t index) {
        EntitySpec resting = cube;
        resting.name = "C" + std::to_string(index);
        resting.position.z += dz;
        s.entities.insert(s.entities.begin() + static_cast<std::ptrdiff_t>(index), resting);
      };
      restingAt(0.5, 1);   // between the cube and its rider
      restingAt(-0.5, 0);  // before them
      restingAt(1.0, 4);   // after them
      auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
      const double rest = dropTouchHeight(DropCase{"cube", "0.2", 0.5 * c.sizeA, support});  // m, its centre at rest
      double lowest = rest, highest = rest;
      runScript(s, s.settings, *sim, [&](const Simulation& now) {
        for (const auto& entity : dynamic_cast<const World&>(now).entities()) {
          if (entity->name().front() != 'C') continue;
          const double y = entity->body()->getCenterOfMassPosition().y();
          lowest = std::min(lowest, y), highest = std::max(highest, y);
        }
      });
      EXPECT_NEAR(lowest, rest, 1e-5) << support << ", " << rate << " Hz";
      EXPECT_NEAR(highest, rest, 1e-5) << support << ", " << rate << " Hz";
    }
  }
}

}  // namespace
}  // namespace tabletop
