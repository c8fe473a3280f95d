// compare's verdicts: each reason on a constructed outcome, and the two
// places where full physics must differ from the rules, pinned on the
// project's scenes.

#include "sim/ModeComparison.h"

#include <gtest/gtest.h>

#include "scenario/ScenarioLoader.h"

namespace tabletop {
namespace {

ModeOutcome at(double x, double z, EntityPositionStatus status = EntityPositionStatus::OnTable,
               std::optional<DirectionDef> edge = std::nullopt) {
  ModeOutcome o;
  o.state.position = {x, 0.8, z};
  o.state.status = status;
  o.edge = edge;
  o.trajectory.points = {{0, 0.8, 0}, o.state.position};
  return o;
}

std::string judge(const ModeOutcome& rules, ModeOutcome other) {
  other.fromRules = (other.state.position - rules.state.position).length();
  return verdict({0, 0.8, 0}, rules, other);
}

TEST(Verdict, NamesEachReason) {
  const auto drop = EntityPositionStatus::FinishDropSimulation;
  const ModeOutcome rules = at(0.3, 0.0);
  EXPECT_EQ(judge(rules, at(0.3005, 0.0)), "agrees");  // 0.5 mm
  EXPECT_EQ(judge(rules, at(0.2, 0.0)), "diverges: stopped short");
  EXPECT_EQ(judge(rules, at(0.4, 0.0)), "diverges: went further");
  EXPECT_EQ(judge(rules, at(0.3, 0.2)), "diverges: went sideways");
  EXPECT_EQ(judge(rules, at(0.9, 0.0, drop, DirectionDef::Right)), "diverges: slid off");
  EXPECT_EQ(judge(at(0.9, 0.0, drop, DirectionDef::Right), at(0.3, 0.0)), "diverges: stayed behind");
  EXPECT_EQ(judge(at(0.9, 0.0, drop, DirectionDef::Right), at(0.0, 0.6, drop, DirectionDef::Front)), "diverges: dropped from another edge");
  EXPECT_EQ(judge(at(0.9, 0.0, drop, DirectionDef::Right), at(1.2, 0.1, drop, DirectionDef::Right)), "agrees");
  ModeOutcome turned = at(0.3, 0.0);
  turned.state.yawDegrees = 15.0;
  EXPECT_EQ(judge(rules, turned), "diverges: rotated");
  ModeOutcome lying = at(0.3, 0.0);
  lying.state.orientation = {std::cos(0.4), std::sin(0.4), 0, 0};  // 46 degrees about X
  EXPECT_EQ(judge(rules, lying), "diverges: tipped");
  ModeOutcome back = at(0.1, 0.0);
  back.trajectory.points = {{0, 0.8, 0}, {0.25, 0.8, 0}, {0.1, 0.8, 0}};
  EXPECT_EQ(judge(rules, back), "diverges: stopped short, bounced back");
  // Every reason that applies, the largest against its threshold first:
  // 0.2 m short is 200 times the 1 mm agreement, 44 degrees 22 times the
  // 2 degrees of a rotation.
  ModeOutcome both = at(0.1, 0.0);
  both.state.yawDegrees = 44.0;
  EXPECT_EQ(judge(rules, both), "diverges: stopped short, rotated");
  both.state.position.x = 0.2995;
  EXPECT_EQ(judge(rules, both), "diverges: rotated");
}

Comparison compareFile(const char* file) {
  const Scenario s = ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/" + file);
  return compareModes(s, s.settings);
}

const EntityComparison& entity(const Comparison& c, const std::string& name) {
  for (const EntityComparison& e : c.entities) {
    if (e.name == name) return e;
  }
  throw std::runtime_error("no entity " + name);
}

// Figure 3-7: A strikes B off its centre of mass. The rules (and compat)
// move B straight on, unturned; in full physics the off-centre contact
// turns both.
TEST(PinnedDifference, MisalignedCubesTurnInFullPhysics) {
  const Comparison c = compareFile("misaligned_cubes.json");
  const EntityComparison& b = entity(c, "B");
  EXPECT_EQ(b.modes[1].verdict, "agrees");
  EXPECT_DOUBLE_EQ(b.modes[0].state.yawDegrees, 0.0);
  EXPECT_DOUBLE_EQ(b.modes[1].state.yawDegrees, 0.0);
  EXPECT_GT(std::abs(b.modes[2].state.yawDegrees), 10.0);
  EXPECT_EQ(b.modes[2].verdict.rfind("diverges: stopped short, rotated", 0), 0u) << b.modes[2].verdict;
  // Every reason that applies, stopping short (0.26 m) the largest against
  // its threshold: the striker, turned aside by the corner it met (which of
  // its turn and its sideways path ranks next hangs on the chaotic
  // corner-to-face contact, and changed with the solver's rounding).
  const std::string& a = entity(c, "A").modes[2].verdict;
  EXPECT_EQ(a.rfind("diverges: stopped short, ", 0), 0u) << a;
  EXPECT_NE(a.find("went sideways"), std::string::npos) << a;
  EXPECT_NE(a.find("rotated"), std::string::npos) << a;
}

// A 20 g sphere strikes a 2 kg one head-on. The rules stop the striker at
// the contact; momentum and restitution (e = 0.64 for the pair) send it
// back: v' = (m1 - e m2) / (m1 + m2) v < 0.
TEST(PinnedDifference, ALightSphereBouncesBackOffAHeavyOne) {
  const Comparison c = compareFile("sphere_bounces_back.json");
  const EntityComparison& light = entity(c, "Light");
  EXPECT_EQ(light.modes[1].verdict, "agrees");
  EXPECT_EQ(light.modes[2].verdict, "diverges: stopped short, bounced back");
  EXPECT_LT(light.modes[2].state.position.x, light.modes[0].state.position.x - 0.01);
}

}  // namespace
}  // namespace tabletop
