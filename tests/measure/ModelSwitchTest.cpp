// The model switches: what each leaves out, and that leaving it out does
// not change what happens.

#include "measure/ModelSwitch.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/StateHash.h"
#include "scenario/ScenarioLoader.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

std::vector<std::string> shippedScenarios() {
  std::vector<std::string> files;
  const std::string dir = std::string(TABLETOP_SOURCE_DIR) + "/scenarios";
  for (const std::string& d : {dir, dir + "/analytic"}) {
    for (const auto& e : std::filesystem::directory_iterator(d)) {
      if (e.path().extension() == ".json") files.push_back(e.path().string());
    }
  }
  return files;
}

int differences(const Settings& a, const Settings& b) {
  return (a.bullet.sleeping != b.bullet.sleeping) + (a.bullet.legsWhenReachable != b.bullet.legsWhenReachable) +
         (a.bullet.floorPairsNearFloor != b.bullet.floorPairsNearFloor) + (a.bullet.broadphase != b.bullet.broadphase);
}

// The defaults first, then each switch flipped alone: one field differs.
TEST(ModelSwitch, ListsTheDefaultsThenEachSwitchFlippedAlone) {
  const Settings base;
  const std::vector<ModelSwitch> all = modelSwitches(base);
  ASSERT_EQ(all.size(), 6u);  // defaults, sleeping, legs, floor pairs, two other broadphases
  EXPECT_EQ(all[0].name, "defaults");
  EXPECT_EQ(differences(all[0].settings, base), 0);
  for (std::size_t i = 1; i < all.size(); ++i) {
    EXPECT_EQ(differences(all[i].settings, base), 1) << all[i].name;
    EXPECT_EQ(all[i].settings.timestep, base.timestep);
  }
}

// The legs, the floor's pairs and the broadphase decide only which pairs
// of bodies Bullet tests; the pairs left out cannot meet. So every shipped
// scene ends bit-identical with each of them flipped (full physics).
TEST(ModelSwitch, PruningSwitchesLeaveEveryShippedOutcomeBitIdentical) {
  for (const std::string& file : shippedScenarios()) {
    const Scenario s = ScenarioLoader::loadFile(file);
    std::uint64_t defaults = 0;
    for (const ModelSwitch& m : modelSwitches(s.settings)) {
      if (m.settings.bullet.sleeping != s.settings.bullet.sleeping) continue;
      auto sim = buildSimulation(s, m.settings, SimulationMode::Bullet);
      const std::uint64_t hash = runScript(s, m.settings, *sim).stateHash;
      if (m.name == "defaults") defaults = hash;
      EXPECT_EQ(hash, defaults) << s.name << " with " << m.name;
    }
  }
}

// With sleeping on, what rests at the start begins asleep, and a moving
// body wakes what it strikes: in report example 2, B (asleep) is struck by
// A and still goes over the right edge.
TEST(ModelSwitch, SleepingBodiesWakeWhenStruck) {
  const Scenario s = ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/example2_two_cubes.json");
  Settings sleeping = s.settings;
  sleeping.bullet.sleeping = true;
  auto sim = buildSimulation(s, sleeping, SimulationMode::Bullet);
  const RunResult r = runScript(s, sleeping, *sim);
  ASSERT_EQ(r.entities.size(), 2u);
  EXPECT_EQ(r.entities[1].status, EntityPositionStatus::FinishDropSimulation);
  EXPECT_LT(r.entities[1].position.y, 0.1);  // on the floor, m
}

}  // namespace
}  // namespace tabletop
