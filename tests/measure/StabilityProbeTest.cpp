// The hard cases (scenarios/hard/, docs/hard-cases.md): each scene run in
// full physics and judged against its stated threshold, in SI units.

#include "measure/StabilityProbe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
#include <string>

#include <gtest/gtest.h>

#include "physics/World.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

Scenario hard(const std::string& name) {
  return ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/hard/" + name + ".json");
}

// Where the first entity's centre is at the end of a full-physics run.
Vec3 probeEnd(const Scenario& s, const Settings& settings) {
  auto sim = buildSimulation(s, settings, SimulationMode::Bullet);
  return runScript(s, settings, *sim).entities.at(0).position;
}

// A scene's settings with the step set from a rate in Hz.
Settings atRate(const Scenario& s, double rate) {
  Settings settings = s.settings;
  settings.timestep = 1.0 / rate;
  return settings;
}

Scenario shipped(const std::string& name) {
  return ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/" + name + ".json");
}

// Every step rate a scene may use, from the slowest to the fastest the
// settings accept (kMaxTimestep, kMinTimestep).
constexpr double kRates[] = {10, 30, 60, 120, 240, 1000, 10000, 100000};

// Towers of ten and twenty 0.1 m cubes stand for 60 s at 60 Hz with
// sleeping off, the solver chosen per island (the default `auto`: the
// loaded islands solved exactly): no cube drifts more than 1 mm from where it started
// (the goal), no contact is deeper than 0.1 mm, and in the last
// second nothing moves faster than 0.1 mm/s. Measured: ten cubes 2e-4 mm,
// 1e-5 mm, 0.7 um/s; twenty cubes 1e-3 mm, 1e-5 mm, 2.6 um/s. Every
// island is solved by the guess of its pressing points, none by the
// pivoting (docs/hard-cases.md: 16 -> 4.6 ms per simulated second).
TEST(HardCase, TallStacksStand) {
  for (const char* name : {"tall_stack_10", "tall_stack_20"}) {
    SCOPED_TRACE(name);
    const Scenario s = hard(name);
    const StabilityReport r = probeStability(s, s.settings);
    ASSERT_TRUE(r.complete) << r.failure;
    EXPECT_NEAR(r.simulated, 60.0, 1e-9);
    EXPECT_LE(r.worstDrift, 1e-3);
    EXPECT_LE(r.worstPenetration, 1e-4);
    EXPECT_LE(r.restSpeed, 1e-4);
    EXPECT_EQ(r.solverUse.guessed, r.solverUse.direct);
    EXPECT_EQ(r.solverUse.direct, 3600);
  }
}

// A 100 kg cube on a 1 kg cube and the other way round (and 1000 kg on
// 1 kg), `auto` for 60 s at 60 Hz: no contact deeper than 0.01 mm
// (measured 1e-5 mm and 2e-3 mm) and no cube drifting more than 0.1 mm
// (measured 1e-5 mm and 4e-3 mm; before the second friction row at 1000:1,
// 11.5 mm in 10 s, RestingLoadTest). With sequential
// impulses (10 iterations) the light base cannot pass its load on: the
// 100:1 stack sinks 22 mm into its base and the heavy cube slides off it
// (drift 355 mm), which the last lines hold as the reason for the setting.
TEST(HardCase, MassRatiosRestWithTheDirectSolver) {
  for (const char* name : {"mass_ratio_100", "mass_ratio_1000"}) {
    SCOPED_TRACE(name);
    const Scenario s = hard(name);
    const StabilityReport r = probeStability(s, s.settings);
    ASSERT_TRUE(r.complete) << r.failure;
    EXPECT_NEAR(r.simulated, 60.0, 1e-9);
    EXPECT_LE(r.worstPenetration, 1e-5);
    EXPECT_LE(r.worstDrift, 1e-4);
    EXPECT_EQ(r.solverUse.guessed, r.solverUse.direct) << "an island at rest left to the pivoting";
  }
  Scenario s = hard("mass_ratio_100");
  s.settings.solver = ContactSolver::SequentialImpulse;
  const StabilityReport iterative = probeStability(s, s.settings);
  EXPECT_GT(iterative.worstPenetration, 5e-3);
  EXPECT_GT(iterative.worstDrift, 0.1);
}

// A pyramid of 55 cubes ten wide stands for 60 s at 60 Hz with no other
// settings: no cube drifts more than 0.5 mm (measured 0.11 mm; 1.76 mm
// before boxes a hair apart were clipped) and in the
// last second nothing moves faster than 0.1 mm/s (measured 0.1 um/s). Its
// one island is too large to pivot, so `auto` gives it the long sweeps in
// 1/120 s parts (IslandSolver::kLongSweeps); with the plain 10 sweeps it
// drifts over 10 mm in 10 s (measured 34 mm; it fell before boxes a hair
// apart were clipped, SolidOnFaceAlgorithm::clipApart), which the last lines hold
// as the reason for them.
TEST(HardCase, PyramidStands) {
  const Scenario s = hard("pyramid_55");
  const StabilityReport r = probeStability(s, s.settings);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_NEAR(r.simulated, 60.0, 1e-9);
  EXPECT_LE(r.worstDrift, 5e-4);
  EXPECT_LE(r.restSpeed, 1e-4);
  EXPECT_GT(r.solverUse.longSwept, 0);
  Settings sweeps = s.settings;
  sweeps.solver = ContactSolver::SequentialImpulse;
  sweeps.duration = 10.0;
  EXPECT_GT(probeStability(s, sweeps).worstDrift, 0.01);
}

// A 1 cm sphere thrown down at 30 m/s never passes through the 4 cm top at
// any step the settings allow: its bottom never goes deeper into the top
// than its own diameter, and it ends resting on the top.
TEST(HardCase, FastSmallSphereNeverPassesThroughTheTop) {
  const Scenario s = hard("fast_small_sphere");
  for (double rate : kRates) {
    const Settings settings = atRate(s, rate);
    const StabilityReport r = probeStability(s, settings);
    ASSERT_TRUE(r.complete) << rate << " Hz: " << r.failure;
    // Measured: 15 nm at 10 Hz and none at 30 Hz and above: the step is
    // cut into parts (World::substeps) and the top's predictive contact,
    // made 2 cm ahead once the top's child box is padded (PaddedShape),
    // stops it at the surface. Before both, 2.5 mm at 10-240 Hz (the
    // swept sphere of half the radius stopped it) and 6.1 mm at 1000 Hz.
    EXPECT_GE(r.lowestOverTop, -0.01) << rate << " Hz";
    const Vec3 end = probeEnd(s, settings);
    // Split impulse takes out 20% of the penetration a step: at 10 Hz 1 mm
    // is left at the end (0.5 s).
    EXPECT_NEAR(end.y, s.table.height + 0.005, 0.0025) << rate << " Hz: it ends on the top";
  }
}

// A 2 cm cube driven at 20 m/s into another 0.3 m away strikes it at every
// step the settings allow, from 10 Hz (2 m a step) to 100 kHz, and never
// passes through it: while both are on the table its centre stays behind
// the other's (measured: at most 3 mm into the other, at 1000 Hz). And the
// strike splits the momentum as a plastic impact of equal masses does
// (restitution 0): each leaves at v/2, with v^2 = 20^2 - 2 mu g (0.28 m)
// after sliding to the other, and both then slide on at mu g. Checked at
// the end of the first step after the strike, t, against
// v/2 - mu g (t - ts) with ts = (20 - v) / (mu g), to 0.5%, at every rate
// whose step ends before the struck cube reaches the table's edge (30 Hz
// up; at 10 Hz it has left the table by then). Measured within 0.05% at
// every such rate. Before fast bodies were stepped in parts and impacts
// were kept out of warm starting (World::substeps, DynamicsWorld), the
// striker kept 14 of its 20 m/s at 240 Hz and the split held only from
// 1 kHz: docs/hard-cases.md.
TEST(HardCase, FastSmallCubeStrikesAndNeverPassesThrough) {
  const Scenario s = hard("fast_small_cubes");
  const double top = s.table.height + 0.01;  // both centres while on the table, m
  const double size = 0.02, mu = 0.3;
  const double g = s.settings.gravity;
  const double strike = std::sqrt(20.0 * 20.0 - 2 * mu * g * (0.3 - size));
  const double strikeTime = (20.0 - strike) / (mu * g);
  const double edge = 0.5 * s.table.width;  // x of the edge the struck cube slides to, m
  for (double rate : kRates) {
    const Settings settings = atRate(s, rate);
    double behind = 1.0;  // least x of the target less x of the striker while both are on the table, m
    bool struck = false;
    double t = 0.0;
    Vec3 afterStrike[2], where;
    const StabilityReport r = probeStability(s, settings, [&](const Simulation& sim) {
      const std::vector<BodyMotion> m = sim.motions();
      if (std::abs(m[0].position.y - top) < 1e-3 && std::abs(m[1].position.y - top) < 1e-3) {
        behind = std::min(behind, m[1].position.x - m[0].position.x);
      }
      if (!struck && m[1].linearVelocity.x > 1.0) {
        struck = true;
        t = sim.time();
        where = m[1].position;
        afterStrike[0] = m[0].linearVelocity, afterStrike[1] = m[1].linearVelocity;
      }
    });
    ASSERT_TRUE(r.complete) << rate << " Hz: " << r.failure;
    EXPECT_TRUE(struck) << rate << " Hz";
    EXPECT_GT(behind, 0.0) << rate << " Hz: the striker passed through";
    if (where.x < edge) {
      const double expected = strike / 2 - mu * g * (t - strikeTime);
      EXPECT_NEAR(afterStrike[0].x, expected, 0.005 * expected) << rate << " Hz: the striker";
      EXPECT_NEAR(afterStrike[1].x, expected, 0.005 * expected) << rate << " Hz: the struck cube";
    } else {
      EXPECT_LT(rate, 30.0) << "the struck cube left the table within a step";
    }
  }
}

// A 5 m cube and a 5 mm cube on the floor rest at their true height, half
// their size, within 1% of their size, at every rate from 60 Hz up; and the
// small one keeps still. Measured at 240 Hz: 2.6 um for the 5 m cube (its
// collision margin is scaled to it, 4 cm rather than a fixed share of its
// size); 2.6 um for the 5 mm cube, 41 um at 60 Hz, 0.15 um at 1000 Hz. The
// small one sank 4.8 mm and jittered at 0.1 m/s while a new contact point
// replaced any kept one within Bullet's 2 cm, which merged all four of its
// corners into one (ContactResult). At 30 Hz it sits 0.16 mm deep, at
// 10 Hz 2 mm: one step of gravity before the contact holds it.
TEST(HardCase, CubesRestAtTheirHeightOnTheFloor) {
  const struct {
    const char* name;
    double size;  // m
  } cubes[] = {{"huge_cube", 5.0}, {"tiny_cube", 0.005}};
  for (const auto& c : cubes) {
    const Scenario s = hard(c.name);
    for (double rate : {60.0, 240.0, 1000.0, 10000.0}) {
      const Settings settings = atRate(s, rate);
      const StabilityReport r = probeStability(s, settings);
      ASSERT_TRUE(r.complete) << c.name << " at " << rate << " Hz: " << r.failure;
      EXPECT_LE(r.worstDrift, 0.01 * c.size) << c.name << " at " << rate << " Hz";
      EXPECT_NEAR(probeEnd(s, settings).y, c.size / 2, 0.01 * c.size) << c.name << " at " << rate << " Hz";
      // At rest: slower than its size in a thousand seconds.
      EXPECT_LE(r.restSpeed, c.size / 1000) << c.name << " at " << rate << " Hz";
    }
  }
}

// Report example 1 with the table and the cube moved 1000 m along X runs
// as it does at the origin, to 1 nm over its three pushes on the table
// (measured 2e-12 m: double precision's spacing at 1000 m is 1.1e-13 m;
// float's, 61 um, would be the whole tolerance of a fine scene). Once the
// cube has fallen and tumbled on the floor the two runs are 3 cm apart, as
// are two runs at the origin 1e-9 m apart at the start: a chaotic tumble,
// not the distance (docs/hard-cases.md).
TEST(HardCase, FarTableBehavesAsAtTheOrigin) {
  Scenario near = shipped("example1_single_cube");
  Scenario far = near;
  constexpr double kAway = 1000.0;
  far.table.centreX += kAway;
  for (EntitySpec& e : far.entities) e.position.x += kAway;
  Settings settings = near.settings;
  settings.duration = 1.0;  // three pushes, on the table throughout
  double worst = 0.0;
  auto a = buildSimulation(near, settings, SimulationMode::Bullet);
  auto b = buildSimulation(far, settings, SimulationMode::Bullet);
  ScriptPlayer pa(near, settings, *a), pb(far, settings, *b);
  pa.runDue();
  pb.runDue();
  while (!pa.finished()) {
    pa.step();
    pb.step();
    const auto ma = a->motions(), mb = b->motions();
    for (std::size_t i = 0; i < ma.size(); ++i) {
      worst = std::max(worst, (mb[i].position - ma[i].position - Vec3{kAway, 0, 0}).length());
    }
  }
  ASSERT_TRUE(pb.finished());
  EXPECT_LE(worst, 1e-9);
}

// The report's examples at 1/30 s do not explode: every run completes
// within the divergence guard's energy bounds, every entity ends where it
// ends at the default 240 Hz (on the table or dropped), and the mechanical
// energy never rises without a push by more than a small share of the
// scene's. It does rise, by penetration recovery lifting bodies that sank
// into what they landed on in a step: measured 0.10% in example 1, 0.42% in
// example 2 (its struck cube, tumbling on the floor, sinks 1.4 cm into it),
// 0.025% in example 3 and 0.016% in example 4 (docs/hard-cases.md); the
// shares below were set after measuring. Before the parts counted a
// turning body's farthest point in full, example 2's cube sank 4.5 cm and
// the scene gained 1.0%. Before fast bodies were stepped in parts
// (World::substeps), example 2's struck cube stopped on the table at 30 Hz
// though it falls off at 240 Hz, so it never landed and gained nothing;
// the others gained 2.6%, 1.4% and 0.7%.
TEST(HardCase, ReportExamplesAtThirtyHertz) {
  const struct {
    const char* name;
    double share;
  } cases[] = {{"example1_single_cube", 0.003}, {"example2_two_cubes", 0.006},
               {"example3_stacked_cubes", 0.0005}, {"example4_two_spheres", 0.0003}};
  for (const auto& c : cases) {
    const Scenario s = shipped(c.name);
    std::vector<EntityState> end[2];
    const double rates[2] = {240.0, 30.0};
    StabilityReport r;
    for (int k = 0; k < 2; ++k) {
      const Settings settings = atRate(s, rates[k]);
      r = probeStability(s, settings, [&](const Simulation& sim) { end[k] = sim.snapshot(); });
      EXPECT_TRUE(r.complete) << c.name << " at " << rates[k] << " Hz: " << r.failure;
    }
    EXPECT_LE(r.energyGain, c.share * r.energyScale) << c.name;
    ASSERT_EQ(end[0].size(), end[1].size());
    for (std::size_t i = 0; i < end[0].size(); ++i) {
      EXPECT_EQ(end[1][i].status, end[0][i].status) << c.name << ": " << end[0][i].name;
    }
  }
}

// Torque-free rotation of the tumbler (free_rotation: a solid box, unturned
// at the start, so its spin in its own axes is the scene's) by Euler's
// equations in body axes,
//   I1 w1' = (I2 - I3) w2 w3 (and cyclically), I1 = m (b^2 + c^2) / 12,
// integrated by classical Runge-Kutta at 10 us (its error in the time
// found is below 1e-9 s): when the spin about the intermediate axis (local
// Y) first changes sign, the middle of the first flip.
double referenceFlipTime(const EntitySpec& box) {
  const double a = box.geometry.width(), b = box.geometry.boxHeight(), c = box.geometry.depth();
  const btVector3 I = (box.mass / 12.0) * btVector3(b * b + c * c, a * a + c * c, a * a + b * b);
  const auto rate = [&](const btVector3& w) {
    return btVector3((I.y() - I.z()) * w.y() * w.z() / I.x(), (I.z() - I.x()) * w.z() * w.x() / I.y(),
                     (I.x() - I.y()) * w.x() * w.y() / I.z());
  };
  const double h = 1e-5;
  btVector3 w(box.spin.x, box.spin.y, box.spin.z);
  for (long i = 0; i < 10'000'000; ++i) {
    const btVector3 k1 = rate(w), k2 = rate(w + 0.5 * h * k1), k3 = rate(w + 0.5 * h * k2), k4 = rate(w + h * k3);
    const btVector3 next = w + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (next.y() < 0.0) return h * (i + w.y() / (w.y() - next.y()));
    w = next;
  }
  return -1.0;
}

// One run of the tumbler with a gyroscopic option: the worst relative
// errors of its angular momentum L = R I R^T w and kinetic energy
// w.I w / 2 over its 10 s, when its intermediate-axis spin first changed
// sign (-1 if never, interpolated within the step), and the probe's report.
struct Tumble {
  double momentum = 0.0;
  double energy = 0.0;
  double flipTime = -1.0;
  StabilityReport report;
};

Tumble tumble(const Scenario& scene, Gyroscopic gyroscopic) {
  Settings settings = scene.settings;
  settings.bullet.gyroscopic = gyroscopic;
  Tumble t;
  btVector3 startMomentum(0, 0, 0), lastSpin(0, 0, 0);
  double startEnergy = -1.0;
  t.report = probeStability(scene, settings, [&](const Simulation& sim) {
    const btRigidBody& body = *dynamic_cast<const World&>(sim).entities()[0]->body();
    const btMatrix3x3& basis = body.getWorldTransform().getBasis();
    const btVector3 inv = body.getInvInertiaDiagLocal();
    const btVector3 w = basis.transpose() * body.getAngularVelocity();
    const btVector3 local(w.x() / inv.x(), w.y() / inv.y(), w.z() / inv.z());
    const btVector3 momentum = basis * local;
    const double energy = 0.5 * w.dot(local);
    if (startEnergy < 0) {
      startEnergy = energy;
      startMomentum = momentum;
    } else if (t.flipTime < 0 && w.y() < 0.0) {
      t.flipTime = sim.time() - settings.timestep * w.y() / (w.y() - lastSpin.y());
    }
    lastSpin = w;
    t.momentum = std::max(t.momentum, double((momentum - startMomentum).length() / startMomentum.length()));
    t.energy = std::max(t.energy, std::abs(energy - startEnergy) / startEnergy);
  });
  return t;
}

// A box spinning at 5 rad/s about its intermediate axis in free flight
// flips over at 3.684 s (Euler's equations, above) and keeps its angular
// momentum and kinetic energy. A body touching nothing turns by Euler's
// equations' exact solution (physics/step/FreeFlight.h), whatever the
// gyroscopic option (which only bodies in contact use): at 240 Hz over
// 10 s the flip within 1e-5 of its time, L and the energy within 1e-6.
// Before, by Bullet's options (docs/free-rotation.md): implicit in body
// or world axes flipped 0.4% early and lost 2.7% of the energy; explicit
// flipped 0.4% late and gained 2.6%; none never flipped.
TEST(HardCase, FreeRotationKeepsMomentumAndEnergy) {
  const Scenario scene = hard("free_rotation");
  const double flip = referenceFlipTime(scene.entities.at(0));
  ASSERT_NEAR(flip, 3.684, 0.001);
  for (Gyroscopic g : kAllGyroscopics) {
    SCOPED_TRACE(toString(g));
    const Tumble t = tumble(scene, g);
    ASSERT_TRUE(t.report.complete) << t.report.failure;
    EXPECT_NEAR(t.flipTime, flip, 1e-5 * flip);
    EXPECT_LE(t.momentum, 1e-6);
    EXPECT_LE(t.energy, 1e-6);
    EXPECT_LE(t.report.energyGain, 1e-6 * t.report.energyScale);
  }
}

// Resting contact: six bodies (cubes, a box with a cube riding on it, an
// upright cylinder, a ball with rolling resistance) pushed into each other
// at 0-1 s, the last one once all has come to rest (1.4 s), then left
// alone to 20 s at the default settings. All come to rest before 2 s
// (measured 1.6 s). From then on no body moves more than 10 um from where
// it stopped (measured 1.1 um over the 18.4 s) and none is faster than
// 1 um/s in the last second (measured 0.015 um/s). The mechanical energy
// never rises without a push by more than 1e-5 of the scene's (measured
// 6.7e-6: the penetration split impulse takes out as bodies settle). The
// thresholds were set after measuring. Run on to 40 s, the creep stays
// 1.1 um; it was 54 um, the cylinder jolting as GJK found one point of
// its rim a step, until cylinders got multipoint contacts
// (ContactDispatcher; docs/hard-cases.md).
TEST(HardCase, RestingContactComesToRestAndStays) {
  const Scenario s = hard("resting_contact");
  double settled = -1.0;  // when all came to rest after the last push
  std::vector<btVector3> where;
  double creep = 0.0;
  const StabilityReport r = probeStability(s, s.settings, [&](const Simulation& sim) {
    const auto& entities = dynamic_cast<const World&>(sim).entities();
    if (settled < 0) {
      const auto& events = sim.events();
      const auto pushes =
          std::count_if(events.begin(), events.end(), [](const Event& e) { return e.type == EventType::Push; });
      if (pushes == static_cast<long>(s.script.size()) - 1 && sim.allAtRest()) {  // all but the wait
        settled = sim.time();
        for (const auto& e : entities) where.push_back(e->body()->getCenterOfMassPosition());
      }
      return;
    }
    for (std::size_t i = 0; i < entities.size(); ++i) {
      creep = std::max(creep, double((entities[i]->body()->getCenterOfMassPosition() - where[i]).length()));
    }
  });
  ASSERT_TRUE(r.complete) << r.failure;
  ASSERT_GT(settled, 0.0) << "never all at rest after the last push";
  EXPECT_LT(settled, 2.0);
  EXPECT_LE(creep, 1e-5);
  EXPECT_LE(r.restSpeed, 1e-6);
  EXPECT_LE(r.energyGain, 1e-5 * r.energyScale);
}

// A starting velocity is full physics only: the report's rules start every
// entity at rest, so the other modes refuse the scene, naming the field.
TEST(HardCase, StartingMotionIsFullPhysicsOnly) {
  const Scenario s = hard("fast_small_sphere");
  for (SimulationMode mode : {SimulationMode::Compat, SimulationMode::Rules}) {
    try {
      buildSimulation(s, s.settings, mode);
      ADD_FAILURE() << toString(mode) << " accepted a starting velocity";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find("/entities/0/velocity"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace tabletop
