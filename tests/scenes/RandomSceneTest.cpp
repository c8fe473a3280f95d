// Hard case 9, randomised robustness: 10,000 seeded random scenes of two to
// five bodies, each pushed one to four times, run in full physics at the
// default settings. SI units.

#include "scenes/RandomScene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "physics/World.h"
#include "sim/SceneBuilder.h"
#include "measure/RandomRunCheck.h"
#include "support/TestName.h"

namespace tabletop {
namespace {

// The same seed gives the same scene; the next seed another. Every scene
// has two to five bodies and one to four pushes, and builds (no body
// overlaps another at the start).
TEST(RandomScene, IsDrawnFromItsSeedAlone) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const Scenario a = RandomScene::make(seed), b = RandomScene::make(seed);
    ASSERT_EQ(a.entities.size(), b.entities.size());
    for (std::size_t i = 0; i < a.entities.size(); ++i) {
      EXPECT_EQ(a.entities[i].geometry.sizes(), b.entities[i].geometry.sizes());
      EXPECT_EQ(a.entities[i].mass, b.entities[i].mass);
      EXPECT_EQ(a.entities[i].on, b.entities[i].on);
    }
    EXPECT_GE(a.entities.size(), 2u) << seed;
    EXPECT_LE(a.entities.size(), 5u) << seed;
    EXPECT_GE(a.script.size(), 1u) << seed;
    EXPECT_LE(a.script.size(), 4u) << seed;
    EXPECT_NO_THROW(buildWorld(a, a.settings)) << seed;
    EXPECT_NE(RandomScene::make(seed + 1).entities.at(0).mass, a.entities.at(0).mass) << seed;
  }
}

// The first scene as drawn by std::mt19937_64, whose sequence the C++
// standard fixes: a change to the drawing shows here before it silently
// changes all 10,000 scenes.
TEST(RandomScene, FirstSceneIsPinned) {
  const Scenario s = RandomScene::make(0);
  std::ostringstream text;
  text.precision(6);
  for (const EntitySpec& e : s.entities) {
    text << e.name << ' ' << static_cast<int>(e.geometry.kind()) << ' ' << e.geometry.sizes()[0] << ' ' << e.mass << ' ' << e.on.name() << '\n';
  }
  for (const Action& a : s.script) text << a.arrow.entity << ' ' << *a.at << ' ' << a.magnitude.value << '\n';
  EXPECT_EQ(text.str(),
            "b0 3 0.0135612 0.0650563 table\n"  // a cone on the table
            "b1 1 0.081117 1.22973 b0\n"        // a sphere on it
            "b2 3 0.093591 0.44803 table\n"
            "b3 2 0.0952175 0.0850838 table\n"  // a box
            "b1 0.0696068 1.8002\n");          // one push, at 0.07 s

}

// One shard of the 10,000 runs, each judged by checkRandomRun
// (measure/RandomRunCheck.h: finite, in the world, no energy gained).
// Bodies do sink into the floor where they land fast: 2.8 cm at most, and a
// 2.3 cm thin cone landing on its rim at 4 m/s spinning at 56 rad/s (seed
// 5049) had its centre 3.3 mm under the floor for two steps before it came
// back out. Measured against the energy bounds: excess under 0.005% at the
// default rate, 0.017% at 60 Hz (seed 6244); gain under 0.15% at the
// default rate, 0.43% at 60 Hz (seed 42). Before a cone's corners over a
// box's face were found where it reached over the edge
// (SolidOnFaceAlgorithm), seeds 3286 and 5510 reached 0.107% and 0.100%
// excess at 60 Hz: a struck cone's far rim sank 10 mm into the box it
// landed on. Failing seeds are listed in the failure message.
class RandomRuns : public testing::TestWithParam<int> {};

constexpr int kShards = 10;
constexpr int kRunsPerShard = 1000;

// The failures of one shard's runs at a step of `timestep` s, one line per seed.
std::vector<std::string> failingRuns(int shard, double timestep) {
  std::vector<std::string> failures;
  for (int k = 0; k < kRunsPerShard; ++k) {
    const std::uint64_t seed = static_cast<std::uint64_t>(shard) * kRunsPerShard + k;
    const RandomRunCheck c = checkRandomRun(seed, timestep);
    if (!c.stable()) failures.push_back("seed " + std::to_string(seed) + ": " + c.reason);
  }
  return failures;
}

std::string listed(const std::vector<std::string>& failures) {
  std::string all;
  for (const std::string& f : failures) all += "\n  " + f;
  return all;
}

TEST_P(RandomRuns, StayFiniteInTheWorldAndGainNoEnergy) {
  const std::vector<std::string> failures = failingRuns(GetParam(), Settings{}.timestep);
  EXPECT_TRUE(failures.empty()) << failures.size() << " of " << kRunsPerShard << " runs failed:" << listed(failures);
}

// The same runs at 60 Hz, the rate a viewer runs at. Measured: all pass,
// energy excess 0.017% at most (seed 6244), gain 0.43% (seed 42). Before
// the direct solver kept every loaded island and solved the push out of
// penetration on the normal rows alone, four bodies passed into the table
// top (seeds 1314, 1563, 1564, 6685): a light cone under a body 20 to 50
// times heavier, swept for a step after the pivoting failed, sank.
TEST_P(RandomRuns, StayFiniteInTheWorldAndGainNoEnergyAt60Hz) {
  const std::vector<std::string> failures = failingRuns(GetParam(), 1.0 / 60.0);
  EXPECT_TRUE(failures.empty()) << failures.size() << " of " << kRunsPerShard << " runs failed:" << listed(failures);
}

INSTANTIATE_TEST_SUITE_P(TenThousand, RandomRuns, testing::Range(0, kShards),
                         [](const testing::TestParamInfo<int>& p) {
                           return test::testName({"shard", std::to_string(p.param)});
                         });

}  // namespace
}  // namespace tabletop
