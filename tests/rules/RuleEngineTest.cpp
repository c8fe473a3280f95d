// The rule engine (mode "rules") against the report's rules worked by hand:
// each expected number below follows from report 3.4, 3.7, 3.8 and the
// choices documented in RuleEngine.h.

#include "rules/RuleEngine.h"

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/DirectionDef.h"
#include "rules/ReportContactFinder.h"

namespace tabletop::rules {
namespace {

constexpr double kTop = 0.75;       // table top height, m
constexpr double kExact = 1e-9;     // kinematics in double: nanometres, m

RuleBody cube(const std::string& name, double side, double x, double z, int support = kOnTable,
              double baseTop = kTop) {
  RuleBody b;
  b.name = name;
  b.shape = ShapeKind::Cube;
  b.halfExtents = {side / 2, side / 2, side / 2};
  b.below = b.above = side / 2;
  b.position = {x, baseTop + side / 2, z};
  b.support = support;
  return b;
}

RuleBody sphere(const std::string& name, double radius, double x, double z) {
  RuleBody b;
  b.name = name;
  b.shape = ShapeKind::Sphere;
  b.halfExtents = {radius, radius, radius};
  b.below = b.above = radius;
  b.position = {x, kTop + radius, z};
  return b;
}

std::unique_ptr<RuleEngine> engine(std::vector<RuleBody> bodies) {
  Settings s;
  s.timestep = 1.0 / 240.0;
  return std::make_unique<RuleEngine>("rules", s, TableSpec{}, std::move(bodies),
                                      std::make_unique<ReportContactFinder>());
}

void push(RuleEngine& e, const std::string& name, DirectionDef face, double step) {
  Arrow a;
  a.entity = name;
  a.face = face;
  e.push(a, {PushMagnitude::Kind::Step, step});
}

void runToRest(RuleEngine& e, double limit = 20.0) {
  while (!e.allAtRest() && e.time() < limit) e.step();
  ASSERT_TRUE(e.allAtRest());
}

const Event* first(const RuleEngine& e, EventType type, const std::string& entity) {
  for (const Event& ev : e.events()) {
    if (ev.type == type && ev.entity == entity) return &ev;
  }
  return nullptr;
}

// Report 3.8: X' = X + Step cos(Angle), Z' = Z - Step sin(Angle), for a
// cube turned by 30 degrees pushed on its Left face.
TEST(RuleEngine, APushMovesOneStepAlongTheArrow) {
  auto e = engine({cube("A", 0.1, 0.0, 0.0)});
  e->rotate("A", 30.0);
  push(*e, "A", DirectionDef::Left, 0.2);
  runToRest(*e);
  const Vec3 p = e->bodies()[0].position;
  EXPECT_NEAR(p.x, 0.2 * std::cos(convertAngle(30.0)), kExact);
  EXPECT_NEAR(p.z, -0.2 * std::sin(convertAngle(30.0)), kExact);
  EXPECT_NEAR(p.y, kTop + 0.05, kExact);
  // At the constant drive speed the step takes step / speed seconds.
  EXPECT_NEAR(first(*e, EventType::AtRest, "A")->t, 0.2 / RuleEngine::kDriveSpeed, kExact);
}

// Report 3.7, straight-line transfer: A meets B after the gap, then both
// move the rest of the step along the push; B keeps its Z although it is
// struck off-centre (not aligned, report 3.5).
TEST(RuleEngine, AStruckCubeMovesTheSameRemainingDistanceInTheSameDirection) {
  auto e = engine({cube("A", 0.1, -0.3, 0.0), cube("B", 0.1, 0.0, 0.06)});
  push(*e, "A", DirectionDef::Left, 0.5);
  runToRest(*e);
  const double gap = 0.3 - 0.1;  // centre distance minus the half sides
  EXPECT_NEAR(e->bodies()[0].position.x, -0.3 + 0.5, kExact);
  EXPECT_NEAR(e->bodies()[1].position.x, 0.0 + (0.5 - gap), kExact);
  EXPECT_DOUBLE_EQ(e->bodies()[1].position.z, 0.06);
  const Event* contact = first(*e, EventType::ContactBegin, "A");
  ASSERT_NE(contact, nullptr);
  EXPECT_EQ(contact->other, "B");
  EXPECT_NEAR(contact->t, gap / RuleEngine::kDriveSpeed, kExact);
}

// Report 3.6.1: cubes whose Z extents only touch still collide (touching
// sideways is overlap); a hair apart, A passes B.
TEST(RuleEngine, SidewaysTouchingCollidesAndAGapPasses) {
  auto touching = engine({cube("A", 0.1, -0.3, 0.0), cube("B", 0.1, 0.0, 0.1)});
  push(*touching, "A", DirectionDef::Left, 0.5);
  runToRest(*touching);
  EXPECT_GT(touching->bodies()[1].position.x, 0.1);
  auto apart = engine({cube("A", 0.1, -0.3, 0.0), cube("B", 0.1, 0.0, 0.1 + 1e-6)});
  push(*apart, "A", DirectionDef::Left, 0.5);
  runToRest(*apart);
  EXPECT_DOUBLE_EQ(apart->bodies()[1].position.x, 0.0);
  EXPECT_EQ(first(*apart, EventType::ContactBegin, "A"), nullptr);
}

// Report 3.7, stacked cubes: pushing the lower one carries the upper one.
TEST(RuleEngine, ACubeRestingOnAPushedCubeIsCarried) {
  auto e = engine({cube("Big", 0.2, -0.2, 0.0), cube("Small", 0.08, -0.15, 0.02, 0, kTop + 0.2)});
  push(*e, "Big", DirectionDef::Back, 0.3);  // Back: towards +Z
  runToRest(*e);
  EXPECT_NEAR(e->bodies()[0].position.z, 0.3, kExact);
  EXPECT_NEAR(e->bodies()[1].position.z, 0.32, kExact);
  EXPECT_NEAR(e->bodies()[1].position.x, -0.15, kExact);
  EXPECT_EQ(e->bodies()[1].support, 0);
}

// Report 3.7: the pushed upper cube slides until its centre passes the
// lower one's edge, then (our choice) clears it by its half side and falls
// straight onto the table, whatever remains of the step.
TEST(RuleEngine, APushedUpperCubeSlidesOffItsBaseOntoTheTable) {
  auto e = engine({cube("Big", 0.2, -0.2, 0.2), cube("Small", 0.08, -0.2, 0.2, 0, kTop + 0.2)});
  push(*e, "Small", DirectionDef::Left, 0.45);
  runToRest(*e);
  const RuleBody& small = e->bodies()[1];
  EXPECT_NEAR(small.position.x, -0.2 + 0.1 + 0.04, kExact);
  EXPECT_NEAR(small.position.y, kTop + 0.04, kExact);
  EXPECT_EQ(small.support, kOnTable);
  EXPECT_EQ(small.status, EntityPositionStatus::OnTable);
  EXPECT_DOUBLE_EQ(e->bodies()[0].position.x, -0.2);
  // It falls 0.2 m from rest: t = sqrt(2 h / g) after clearing.
  const Event* lands = first(*e, EventType::Lands, "Small");
  ASSERT_NE(lands, nullptr);
  EXPECT_EQ(lands->on, Support::table());
  EXPECT_NEAR(lands->t, 0.14 / RuleEngine::kDriveSpeed + std::sqrt(2 * 0.2 / 9.81), 1e-6);
}

// Report 3.4: a target past the edge moves the entity to the edge first;
// its status then names the edge; it clears the edge and falls to the
// ground, which ends the drop (FinishDropSimulation).
TEST(RuleEngine, ATargetPastTheEdgeDropsTheEntityThere) {
  auto e = engine({cube("A", 0.1, 0.4, 0.0)});
  push(*e, "A", DirectionDef::Left, 0.5);
  runToRest(*e);
  const Event* leaves = first(*e, EventType::LeavesTable, "A");
  ASSERT_NE(leaves, nullptr);
  EXPECT_EQ(leaves->edge, DirectionDef::Right);
  EXPECT_NEAR(leaves->t, (0.6 - 0.4) / RuleEngine::kDriveSpeed, kExact);
  const RuleBody& a = e->bodies()[0];
  EXPECT_EQ(a.status, EntityPositionStatus::FinishDropSimulation);
  EXPECT_EQ(a.support, kOnGround);
  EXPECT_NEAR(a.position.x, 0.6 + 0.05, kExact);
  EXPECT_NEAR(a.position.y, 0.05, kExact);
}

// Pushing the big cube: both drop together off the edge (report 3.7).
TEST(RuleEngine, ACarriedCubeDropsWithItsBase) {
  auto e = engine({cube("Big", 0.2, 0.35, 0.0), cube("Small", 0.08, 0.35, 0.0, 0, kTop + 0.2)});
  push(*e, "Big", DirectionDef::Left, 0.4);
  runToRest(*e);
  for (const RuleBody& b : e->bodies()) EXPECT_EQ(b.status, EntityPositionStatus::FinishDropSimulation) << b.name;
  EXPECT_NEAR(e->bodies()[1].position.y, 0.2 + 0.04, kExact);  // still on Big, on the ground
  EXPECT_EQ(e->bodies()[1].support, 0);
}

// Report 3.7, two spheres: Step1 = D cos^2(theta) along the line of centres,
// Step2 = min(D sin^2(theta), Step1) across it, with Step1 >= Step2.
TEST(RuleEngine, TwoSpheresSplitTheRemainingStep) {
  const double r = 0.04, offset = 0.03, D0 = 0.5;
  auto e = engine({sphere("S", r, -0.3, offset), sphere("B", r, 0.0, 0.0)});
  push(*e, "S", DirectionDef::Left, D0);
  runToRest(*e);
  const double reach = 2 * r;
  const double contactX = -std::sqrt(reach * reach - offset * offset);  // S's centre at contact
  const double D = D0 - (contactX + 0.3);
  const double sine = offset / reach, cosine = std::sqrt(1 - sine * sine);
  const double step1 = D * cosine * cosine;
  const double step2 = std::min(D * sine * sine, step1);
  const Vec3 b = e->bodies()[1].position;
  const Vec3 s = e->bodies()[0].position;
  // B moves along the line of centres n = (cos, 0, -sin).
  EXPECT_NEAR(b.x, step1 * cosine, kExact);
  EXPECT_NEAR(b.z, -step1 * sine, kExact);
  // S moves across it: (sin, 0, cos).
  EXPECT_NEAR(s.x, contactX + step2 * sine, kExact);
  EXPECT_NEAR(s.z, offset + step2 * cosine, kExact);
  EXPECT_GE(step1, step2);
}

// A glancing blow (theta > 45 degrees) would give the striker more than the
// struck sphere; the cap keeps Step1 >= Step2.
TEST(RuleEngine, AGlancingSphereBlowKeepsStep1AtLeastStep2) {
  auto e = engine({sphere("S", 0.04, -0.3, 0.07), sphere("B", 0.04, 0.0, 0.0)});
  push(*e, "S", DirectionDef::Left, 0.6);
  runToRest(*e);
  const Vec3 b0{0.0, 0.0, 0.0};
  const Vec3 contact{-std::sqrt(0.08 * 0.08 - 0.07 * 0.07), 0.0, 0.07};
  const double step1 = std::hypot(e->bodies()[1].position.x - b0.x, e->bodies()[1].position.z - b0.z);
  const double step2 = std::hypot(e->bodies()[0].position.x - contact.x, e->bodies()[0].position.z - contact.z);
  EXPECT_GT(step1, 0.0);
  EXPECT_NEAR(step2, step1, kExact);
}

TEST(RuleEngine, RefusesPushesItCannotCarryOut) {
  auto e = engine({cube("A", 0.1, 0.55, 0.0), cube("B", 0.1, -0.3, 0.0)});
  Arrow a;
  a.entity = "A";
  a.face = DirectionDef::Left;
  EXPECT_THROW(e->push(a, {PushMagnitude::Kind::Impulse, 1.0}), std::invalid_argument);
  a.entity = "Nobody";
  EXPECT_THROW(e->push(a, {PushMagnitude::Kind::Step, 0.1}), std::invalid_argument);
  push(*e, "B", DirectionDef::Left, 0.2);
  EXPECT_THROW(push(*e, "B", DirectionDef::Left, 0.2), std::invalid_argument);  // still moving
  push(*e, "A", DirectionDef::Left, 0.2);
  runToRest(*e);
  ASSERT_EQ(e->bodies()[0].status, EntityPositionStatus::FinishDropSimulation);
  try {
    push(*e, "A", DirectionDef::Left, 0.2);
    FAIL() << "a push on an entity on the ground must be refused";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'A' is on the ground (FinishDropSimulation)"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace tabletop::rules

namespace tabletop::rules {
namespace {

// Report 3.4 drops an entity only when its centre is strictly past an
// edge: a push whose target lies on the edge ends there, on the table,
// for targets reached by paths that round either way (a cube at x = -0.1
// pushed 0.7 m ends 1.4e-15 m short of the edge at 0.6, the edge's own
// time then coming a hair before the drive's end), at every rate, and
// from each edge.
TEST(RuleEngine, ATargetExactlyOnAnEdgeStaysOnTheTable) {
  const TableSpec table;
  struct Case {
    double x, z, step;
    DirectionDef face;
  };
  for (const Case& c : {Case{-0.1, 0.0, 0.7, DirectionDef::Left}, Case{0.1, 0.0, 0.7, DirectionDef::Right},
                        Case{0.0, 0.1, 0.3, DirectionDef::Back}, Case{0.0, 0.3, 0.7, DirectionDef::Front},
                        Case{0.2 / 3.0, 0.0, 0.6 - 0.2 / 3.0, DirectionDef::Left}}) {
    for (double rate : {30.0, 60.0, 240.0, 1000.0}) {
      Settings s;
      s.timestep = 1.0 / rate;
      RuleEngine e("rules", s, table, {cube("A", 0.1, c.x, c.z)}, std::make_unique<ReportContactFinder>());
      push(e, "A", c.face, c.step);
      runToRest(e);
      EXPECT_EQ(e.snapshot()[0].status, EntityPositionStatus::OnTable) << c.x << " " << c.step << " at " << rate;
      EXPECT_NEAR(e.snapshot()[0].position.y, kTop + 0.05, kExact);
    }
  }
}

// A rider pushed off its base, landing past a table edge, leaves the table
// there: its status and event name the edge, and it ends on the ground.
TEST(RuleEngine, ARiderSlidingOffItsBasePastTheTableEdgeDrops) {
  RuleEngine e("rules", Settings{}, TableSpec{},
               {cube("A", 0.2, 0.47, 0.0), cube("B", 0.1, 0.47, 0.0, 0, kTop + 0.2)},
               std::make_unique<ReportContactFinder>());
  push(e, "B", DirectionDef::Left, 0.3);
  runToRest(e);
  const std::vector<EntityState> s = e.snapshot();
  EXPECT_EQ(s[1].status, EntityPositionStatus::FinishDropSimulation);
  EXPECT_NEAR(s[1].position.y, 0.05, kExact);
  bool left = false;
  for (const Event& ev : e.events()) {
    left = left || (ev.type == EventType::LeavesTable && ev.entity == "B" && ev.edge == DirectionDef::Right);
  }
  EXPECT_TRUE(left);
}


// Report 3.7 down a row: N cubes in a line with seeded gaps, the first
// pushed along the line. Each struck cube takes the rest of the step, so
// the row closes up behind the first: x_0' = x_0 + step and
// x_k' = max(x_k, x_{k-1}' + side). A second row a hair beside it is passed
// by untouched. Checks the strike search over rows of every length, in
// both axes and senses.
struct RowCase {
  int n;
  DirectionDef face;
  Vec3 along;    // the push's direction for that face at yaw 0
  bool reversed; // bodies listed from the far end (the search's order)
};

class RuleEngineRow : public ::testing::TestWithParam<RowCase> {};

TEST_P(RuleEngineRow, ClosesUpByTheTransferRule) {
  const RowCase c = GetParam();
  const double side = 0.002;
  std::mt19937 random(static_cast<unsigned>(c.n));
  std::uniform_real_distribution<double> gapOf(0.0, side);
  std::vector<double> along;  // centres along the push, m
  double x = -0.5;
  for (int k = 0; k < c.n; ++k) {
    along.push_back(x);
    x += side + gapOf(random);
  }
  std::vector<RuleBody> bodies;
  const Vec3 sideways{c.along.z, 0.0, c.along.x};
  const auto slot = [&](int k, int which) {  // R_k at 0, S_k at 1
    return static_cast<std::size_t>(2 * (c.reversed ? c.n - 1 - k : k) + which);
  };
  for (int j = 0; j < c.n; ++j) {
    const int k = c.reversed ? c.n - 1 - j : j;
    const Vec3 p = c.along * along[k];
    bodies.push_back(cube("R" + std::to_string(k), side, p.x, p.z));
    const Vec3 q = p + sideways * (side * 1.001);
    bodies.push_back(cube("S" + std::to_string(k), side, q.x, q.z));
  }
  Settings s;
  s.timestep = 1.0 / 60.0;
  TableSpec table;
  table.width = table.depth = 2.0;
  RuleEngine e("rules", s, table, std::move(bodies), std::make_unique<ReportContactFinder>());
  const double step = 0.5 * (along.back() - along.front());
  push(e, "R0", c.face, step);
  runToRest(e);
  double expected = along[0] + step;
  for (int k = 0; k < c.n; ++k) {
    if (k > 0) expected = std::max(along[k], expected + side);
    const Vec3 p = e.bodies()[slot(k, 0)].position;
    EXPECT_NEAR(p.dot(c.along), expected, kExact) << "R" << k;
    const Vec3 q = e.bodies()[slot(k, 1)].position;
    EXPECT_NEAR(q.dot(c.along), along[k], kExact) << "S" << k << " moved";
  }
}

std::string rowName(const ::testing::TestParamInfo<RowCase>& info) {
  return std::to_string(info.param.n) + "_cubes_" + std::string(toString(info.param.face)) +
         (info.param.reversed ? "_listed_from_the_far_end" : "");
}

INSTANTIATE_TEST_SUITE_P(Rows, RuleEngineRow,
                         ::testing::Values(RowCase{2, DirectionDef::Left, {1, 0, 0}, false},
                                           RowCase{7, DirectionDef::Right, {-1, 0, 0}, true},
                                           RowCase{40, DirectionDef::Front, {0, 0, -1}, false},
                                           RowCase{40, DirectionDef::Back, {0, 0, 1}, true},
                                           RowCase{300, DirectionDef::Back, {0, 0, 1}, false},
                                           RowCase{300, DirectionDef::Left, {1, 0, 0}, true}),
                         rowName);

}  // namespace
}  // namespace tabletop::rules
