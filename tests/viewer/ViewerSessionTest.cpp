// The interactive viewer's behaviour, without a window: the report's
// controls and the simulate-style ones, against the batch run and the
// push's closed form.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptPlayer.h"
#include "viewer/ViewerSession.h"

namespace tabletop {
namespace {

Scenario example(const std::string& name) {
  return ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/" + name + ".json");
}

ViewerSettings still(SimulationMode mode = SimulationMode::Bullet) {
  ViewerSettings v;
  v.mode = mode;
  v.playScript = false;
  return v;
}

// Lets `seconds` of wall time pass in 60 Hz frames.
void play(ViewerSession& s, double seconds) {
  for (int i = 0; i < static_cast<int>(std::lround(seconds * 60)); ++i) s.advance(1.0 / 60.0);
}

TEST(ViewerSession, SpaceCyclesTheFacesThenTheEntities) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSession s(scenario, scenario.settings, still());
  // The arrow starts where the script first pushes.
  EXPECT_EQ(s.arrow().entity, "A");
  ASSERT_TRUE(s.arrow().face);
  EXPECT_EQ(*s.arrow().face, DirectionDef::Left);
  const DirectionDef order[] = {DirectionDef::Back, DirectionDef::Right, DirectionDef::Front};
  for (DirectionDef d : order) {
    s.cycleArrow();
    EXPECT_EQ(s.arrow().entity, "A");
    EXPECT_EQ(*s.arrow().face, d);
  }
  s.cycleArrow();
  EXPECT_EQ(s.arrow().entity, "B");
  EXPECT_EQ(*s.arrow().face, DirectionDef::Left);
}

TEST(ViewerSession, SpheresTakeTheFourWorldAngles) {
  const Scenario scenario = example("example4_two_spheres");
  ViewerSession s(scenario, scenario.settings, still());
  EXPECT_EQ(s.arrow().entity, "Small");
  for (double angle : {90.0, 180.0, 270.0}) {
    s.cycleArrow();
    EXPECT_FALSE(s.arrow().face);
    EXPECT_DOUBLE_EQ(s.arrow().angleDegrees, angle);
  }
  s.cycleArrow();
  EXPECT_EQ(s.arrow().entity, "Big");
}

// G is a scripted push made by hand: the same code, so the same numbers,
// bit for bit, as a script pushing at the same step; and the step's closed
// form holds: a cube alone travels the step (1 %).
TEST(ViewerSession, GPushesLikeTheScriptAndTravelsTheStep) {
  Scenario scenario = example("example1_single_cube");
  scenario.script.clear();
  ViewerSettings v = still();
  v.step = 0.2;
  ViewerSession s(scenario, scenario.settings, v);
  play(s, 0.5);
  const double pushedAt = s.simulation().time();
  const Vec3 before = s.simulation().snapshot().front().position;
  s.pushArrowed();
  play(s, 2.0);
  const double endTime = s.simulation().time();
  const Vec3 after = s.simulation().snapshot().front().position;
  EXPECT_NEAR(after.x - before.x, 0.2, 0.002) << "a Left push moves +X by the step";
  EXPECT_NEAR(after.z - before.z, 0.0, 0.002);

  Scenario scripted = scenario;
  Action push;
  push.type = Action::Type::Push;
  push.at = pushedAt;
  push.arrow = s.arrow();
  push.magnitude = {PushMagnitude::Kind::Step, 0.2};
  scripted.script.push_back(push);
  const auto batch = buildSimulation(scripted, scripted.settings, SimulationMode::Bullet);
  ScriptPlayer player(scripted, scripted.settings, *batch);
  player.runDue();
  while (batch->time() < endTime - 1e-9) player.step();
  EXPECT_EQ(batch->steps(), s.simulation().steps());
  EXPECT_EQ(batch->snapshot().front().position, after);
}

TEST(ViewerSession, TheScriptPlaysOnStartAsInABatchRun) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSettings v;
  ViewerSession s(scenario, scenario.settings, v);
  play(s, 2.0);
  const auto batch = buildSimulation(scenario, scenario.settings, SimulationMode::Bullet);
  ScriptPlayer player(scenario, scenario.settings, *batch);
  player.runDue();
  while (batch->steps() < s.simulation().steps()) player.step();
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(batch->snapshot()[i].position, s.simulation().snapshot()[i].position) << i;
  }
  EXPECT_EQ(s.simulation().snapshot()[1].status, EntityPositionStatus::FinishDropSimulation);
}

TEST(ViewerSession, PlusAndMinusTurnTheViewOrTheEntities) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSession s(scenario, scenario.settings, still());
  const double yaw = s.camera().yawDegrees;
  s.rotate(+1);
  EXPECT_NEAR(s.camera().yawDegrees, yaw - 15.0, 1e-9) << "the scene turns counterclockwise, the eye clockwise";
  EXPECT_NEAR(s.simulation().snapshot().front().yawDegrees, 0.0, 1e-9);
  s.rotate(-1);
  EXPECT_NEAR(s.camera().yawDegrees, yaw, 1e-9);

  s.setRotationTarget(RotationTarget::EntitiesOnTable);
  s.rotate(+1);
  EXPECT_NEAR(s.camera().yawDegrees, yaw, 1e-9);
  for (const EntityState& e : s.simulation().snapshot()) EXPECT_NEAR(e.yawDegrees, 15.0, 1e-6) << e.name;
}

TEST(ViewerSession, ResetPutsEverythingBack) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSession s(scenario, scenario.settings, still());
  const std::vector<EntityState> initial = s.simulation().snapshot();
  s.pushArrowed();
  play(s, 1.0);
  EXPECT_FALSE(s.simulation().snapshot().front().position == initial.front().position);
  s.reset(false);
  EXPECT_EQ(s.simulation().time(), 0.0);
  for (std::size_t i = 0; i < initial.size(); ++i) {
    EXPECT_EQ(s.simulation().snapshot()[i].position, initial[i].position);
  }
}

TEST(ViewerSession, PauseSingleStepAndSlowMotion) {
  const Scenario scenario = example("example2_two_cubes");
  const double dt = scenario.settings.timestep;
  ViewerSession s(scenario, scenario.settings, still());
  s.togglePause();
  play(s, 0.5);
  EXPECT_EQ(s.simulation().time(), 0.0);
  s.singleStep();
  EXPECT_NEAR(s.simulation().time(), dt, 1e-12);
  s.togglePause();

  s.setSpeed(0.25);
  const double t0 = s.simulation().time();
  play(s, 1.0);
  EXPECT_NEAR(s.simulation().time() - t0, 0.25, dt) << "slow motion x1/4";
  EXPECT_NEAR(s.realTimeFactor(), 0.25, 0.02);

  // A long stall costs at most a quarter second of steps.
  s.setSpeed(1.0);
  const double t1 = s.simulation().time();
  s.advance(10.0);
  EXPECT_LE(s.simulation().time() - t1, 0.25 + dt);
}

std::string joined(const std::vector<std::string>& lines) {
  std::string all;
  for (const std::string& line : lines) all += line + "\n";
  return all;
}

// The overlay names the arrowed entity and counts the rest; L lists every
// one; I hides it all.
TEST(ViewerSession, OverlaySaysTimeModeArrowAndStatuses) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSession s(scenario, scenario.settings, still(SimulationMode::Rules));
  std::string all = joined(s.overlay(40));
  EXPECT_NE(all.find("mode rules"), std::string::npos) << all;
  EXPECT_NE(all.find("t 0.000 s"), std::string::npos) << all;
  EXPECT_NE(all.find("arrow: A, Left face, step 0.880 m"), std::string::npos) << all;
  EXPECT_NE(all.find("A  OnTable"), std::string::npos) << all;
  EXPECT_EQ(all.find("B  OnTable"), std::string::npos) << all;
  EXPECT_NE(all.find("2 entities (L: list them)"), std::string::npos) << all;
  s.toggleEntityList();
  all = joined(s.overlay(40));
  EXPECT_NE(all.find("A  OnTable"), std::string::npos) << all;
  EXPECT_NE(all.find("B  OnTable"), std::string::npos) << all;
  s.toggleOverlay();
  EXPECT_TRUE(s.overlay(40).empty());
}

// With the 55-cube pyramid listed, the overlay keeps to the lines the
// window has and says how many entities it leaves out.
TEST(ViewerSession, OverlayFitsAnyNumberOfEntities) {
  const Scenario scenario = ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/hard/pyramid_55.json");
  ViewerSession s(scenario, scenario.settings, still(SimulationMode::Rules));
  EXPECT_LE(s.overlay(40).size(), 6u) << "without L: the arrowed entity and a count";
  s.toggleEntityList();
  for (std::size_t most : {4u, 10u, 30u}) {
    const std::vector<std::string> lines = s.overlay(most);
    EXPECT_EQ(lines.size(), most);
    EXPECT_NE(joined(lines).find(" more (L: fewer)"), std::string::npos) << joined(lines);
  }
  EXPECT_EQ(s.overlay(100).size(), 3u + 55u) << "all of them when they fit";
}

// F fits the scene as it is now, keeping the direction; T makes the
// camera's target follow the arrowed entity as it moves; Tab moves the
// arrow (and a followed camera) to the next entity.
TEST(ViewerSession, CameraFitsFollowsAndCycles) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSettings v = still();
  v.camera = "corner";
  ViewerSession s(scenario, scenario.settings, v);
  const double yaw = s.camera().yawDegrees;
  s.camera().zoom(10.0);
  s.fitCamera(4.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.camera().yawDegrees, yaw);
  for (const EntityState& e : s.simulation().snapshot()) {
    const auto p = s.camera().project(e.position, 960, 720);
    ASSERT_TRUE(p);
    EXPECT_GT(p->column, 0.0);
    EXPECT_LT(p->column, 960.0);
    EXPECT_GT(p->row, 0.0);
    EXPECT_LT(p->row, 720.0);
  }
  s.toggleFollow();
  EXPECT_EQ(s.followed(), "A");
  s.pushArrowed();
  play(s, 1.0);
  const Vec3 a = s.simulation().snapshot()[0].position;
  EXPECT_LT((s.camera().target - a).length(), 1e-12) << "the target is A's centre";
  s.nextEntity();
  EXPECT_EQ(s.arrow().entity, "B");
  EXPECT_EQ(s.followed(), "B");
  EXPECT_LT((s.camera().target - s.simulation().snapshot()[1].position).length(), 1e-12);
  s.toggleFollow();
  EXPECT_EQ(s.followed(), "");
}

// A click on an entity's image puts the arrow on it, on the face turned
// towards the eye; a click on nothing leaves the arrow where it was.
TEST(ViewerSession, AClickPicksTheEntityUnderIt) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSettings v = still();
  v.camera = "front";
  ViewerSession s(scenario, scenario.settings, v);
  const auto b = s.camera().project(s.simulation().snapshot()[1].position, 960, 720);
  ASSERT_TRUE(b);
  EXPECT_TRUE(s.pick(b->column + 2, b->row - 2, 960, 720));
  EXPECT_EQ(s.arrow().entity, "B");
  ASSERT_TRUE(s.arrow().face);
  EXPECT_EQ(*s.arrow().face, DirectionDef::Front) << "the front camera looks from +Z at the Front face";
  EXPECT_FALSE(s.pick(5, 5, 960, 720)) << "the sky";
  EXPECT_EQ(s.arrow().entity, "B");
  s.camera().orbit(90.0, 0.0);  // now from +X: the Right face
  const auto a = s.camera().project(s.simulation().snapshot()[0].position, 960, 720);
  ASSERT_TRUE(a);
  // Whichever cube is nearer under that pixel is picked, on its Right face.
  EXPECT_TRUE(s.pick(a->column, a->row, 960, 720));
  ASSERT_TRUE(s.arrow().face);
  EXPECT_EQ(*s.arrow().face, DirectionDef::Right);
}

// A camera that follows an entity the scene does not have is refused.
TEST(ViewerSession, FollowingNoEntityIsRefused) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSettings v = still();
  v.camera = "follow:C";
  EXPECT_THROW(ViewerSession(scenario, scenario.settings, v), std::invalid_argument);
  v.camera = "follow:B";
  ViewerSession s(scenario, scenario.settings, v);
  EXPECT_EQ(s.followed(), "B");
}

// The rules refuse pushes the report's algorithm cannot make; the viewer
// says why instead of failing.
TEST(ViewerSession, ARefusedPushIsAMessage) {
  const Scenario scenario = example("example2_two_cubes");
  ViewerSession s(scenario, scenario.settings, still(SimulationMode::Rules));
  s.pushArrowed();
  s.pushArrowed();  // A is still moving from the first
  EXPECT_NE(s.overlay(40).back().find("cannot push"), std::string::npos) << s.overlay(40).back();
}

// A scene that diverges pauses the viewer with the reason instead of
// drawing garbage; play stays off until reset, which starts it again.
TEST(ViewerSession, DivergencePausesWithTheReasonUntilReset) {
  const Scenario scenario = ScenarioLoader::loadText(R"({"version": 1, "name": "absurd",
      "settings": {"timestep": 0.1},
      "entities": [{"name": "A", "shape": "cube", "size": 0.01, "position": [0, 0], "mass": 0.0001}],
      "script": [{"push": {"entity": "A", "direction": "Left", "impulse": 1e6}}]})",
                                                     "absurd.json");
  ViewerSettings v;
  ViewerSession s(scenario, scenario.settings, v);
  play(s, 0.5);
  EXPECT_TRUE(s.diverged());
  EXPECT_TRUE(s.paused());
  EXPECT_DOUBLE_EQ(s.simulation().time(), 0.1);
  const std::vector<std::string> lines = s.overlay(40);
  bool said = false;
  for (const std::string& line : lines) said = said || line.find("diverged at t = 0.1 s: entity 'A'") != std::string::npos;
  EXPECT_TRUE(said);
  s.togglePause();
  EXPECT_TRUE(s.paused());
  s.reset(false);
  EXPECT_FALSE(s.diverged());
  EXPECT_FALSE(s.paused());
}

}  // namespace
}  // namespace tabletop
