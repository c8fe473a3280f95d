// Restitution in every direction that gravity gives: a body dropped on the
// floor, on the table or on a heavy slab resting on the floor rebounds
// with e times its impact speed, at its own time inside the step, at every
// rate; e = 0 stops it dead; no step adds energy. Checked over shape x
// support x e x rate against the closed form of the bounce, computed here:
//   falling from h above touch: impact at t0 = sqrt(2 h / g), speed
//   v = g t0; then height above touch e v s - g s^2 / 2, s = t - t0, until
//   it lands again at s = 2 e v / g.
// Tolerance: 0.1 mm on the centre's height at every step until just before
// the second landing (the first at rebounds of e = 0). Bodies land flat:
// spheres and cubes of two sizes (a cube on a face), cylinders (a tall one,
// a flat one, a truncated cone) on their base.
//
// A cylinder used to tip as it landed (one rim point at first touch), and
// a landing on a body resting on the floor was 0.3-1.2 mm off at 30 and
// 60 Hz; both now hold at every rate (docs/bullet-corrections.md). The
// large ball and cube landed on the floor 9.8 mm off at 60 Hz: a step
// that starts more than the 2 cm ahead at which points are made, short of
// a quarter of the body's size (which would cut it into parts), saw no
// impact with the plane, and they sank a step into it.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/Simulation.h"
#include "scenes/LawScenes.h"
#include "sim/SceneBuilder.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;          // m/s^2, the scenario default
constexpr double kTolerance = 1e-4;  // m

class Restitution : public testing::TestWithParam<DropCase> {};

TEST_P(Restitution, ReboundsWithETimesTheImpactSpeed) {
  const DropCase c = GetParam();
  const Scenario s = dropScene(c);
  std::unique_ptr<Simulation> sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
  const std::size_t a = s.entities.size() - 1;
  // No step adds energy: m g y + m v^2 / 2 (the body lands flat and does
  // not turn) never rises above its start, to 1e-9 of it.
  const double start = kG * (dropTouchHeight(c) + kDropHeight);
  double worst = 0.0, worstAt = 0.0, gain = 0.0;
  while (sim->time() + s.settings.timestep <= dropEnd(c, kG)) {
    sim->step();
    const double t = sim->time(), exact = dropHeight(c, kG, t);
    const EntityState body = sim->snapshot()[a];
    const double error = std::abs(body.position.y - exact);
    if (error > worst) worst = error, worstAt = t;
    const Vec3& u = body.linearVelocity;
    gain = std::max(gain, kG * body.position.y + 0.5 * (u.x * u.x + u.y * u.y + u.z * u.z) - start);
  }
  EXPECT_LE(worst, kTolerance) << describe(c) << ": worst at t = " << worstAt << " s";
  EXPECT_LE(gain, 1e-9 * start) << describe(c) << ": energy gained, J per kg";
}

// A truncated cone's centre of mass above its base (radius `base`, the
// other `top`, height h): h (R^2 + 2 R r + 3 r^2) / (4 (R^2 + R r + r^2)).
double frustumCentroid(double base, double top, double h) {
  return h * (base * base + 2 * base * top + 3 * top * top) / (4 * (base * base + base * top + top * top));
}

std::vector<DropCase> cases() {
  const struct {
    const char* shape;
    const char* size;
    double below;
  } shapes[] = {{"sphere", "0.05", 0.05},
                {"sphere", "0.1", 0.1},
                {"cube", "0.1", 0.05},
                {"cube", "0.2", 0.1},
                {"cylinder", "[0.05, 0.05, 0.1]", 0.05},
                {"cylinder", "[0.08, 0.08, 0.03]", 0.015},
                {"cylinder", "[0.05, 0.03, 0.1]", frustumCentroid(0.05, 0.03, 0.1)}};
  std::vector<DropCase> all;
  for (const auto& shape : shapes) {
    for (const char* support : kLawSupports) {
      for (double e : {0.0, 0.5, 0.9}) {
        for (double rate : {30.0, 60.0, 240.0, 1000.0, 10000.0}) {
          all.push_back({shape.shape, shape.size, shape.below, support, e, rate});
        }
      }
    }
  }
  return all;
}

// sphere_0p05_table_e0p5_60Hz
std::string name(const testing::TestParamInfo<DropCase>& p) {
  const DropCase& c = p.param;
  return test::testName({c.shape, c.size, c.support, "e" + test::number(c.restitution), test::number(c.rate) + "Hz"});
}

INSTANTIATE_TEST_SUITE_P(ShapeSupportRate, Restitution, testing::ValuesIn(cases()), name);

}  // namespace
}  // namespace tabletop
