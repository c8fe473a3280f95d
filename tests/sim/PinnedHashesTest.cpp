// Determinism, pinned: the state_hash of every shipped scenario in every
// mode, as golden values. A change in these means the physics changed (a
// Bullet upgrade, a setting, a code change): if it was intended, run
//   build/src/app/tabletop run scenarios/NAME.json --mode MODE
// and copy the new hash here, saying why in the commit.
//
// What makes them reproducible: double-precision Bullet (Debian's float64
// build), -ffp-contract=off (no fused multiply-adds chosen by the
// optimiser), x86-64's SSE arithmetic, a fixed timestep, sleeping off,
// bodies added in scenario order (Bullet's pair cache and solver order
// follow insertion), and no randomisation in the solver
// (SOLVER_RANDMIZE_ORDER unset). They hold at any optimisation level and
// under the sanitizers; a float build gives other values, so it skips.

#include <string>

#include <gtest/gtest.h>

#include "core/StateHash.h"
#include "scenario/ScenarioLoader.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

struct Pinned {
  const char* scenario;
  SimulationMode mode;
  const char* hash;
};

void PrintTo(const Pinned& p, std::ostream* os) { *os << p.scenario << " " << toString(p.mode); }

class PinnedHash : public ::testing::TestWithParam<Pinned> {};

TEST_P(PinnedHash, IsUnchanged) {
#ifndef BT_USE_DOUBLE_PRECISION
  GTEST_SKIP() << "the golden values are those of the double-precision build";
#endif
  const Pinned& p = GetParam();
  const Scenario s =
      ScenarioLoader::loadFile(std::string(TABLETOP_SOURCE_DIR) + "/scenarios/" + p.scenario + ".json");
  const RunResult r = test::runScene(s, p.mode);
  EXPECT_EQ(formatHash(r.stateHash), p.hash)
      << p.scenario << " in mode " << toString(p.mode)
      << ": the outcome changed. If the physics change was intended, update the golden value in "
         "tests/sim/PinnedHashesTest.cpp and say why in the commit.";
}

INSTANTIATE_TEST_SUITE_P(
    Shipped, PinnedHash,
    ::testing::Values(Pinned{"example1_single_cube", SimulationMode::Bullet, "549ef547644de115"},
                      Pinned{"example1_single_cube", SimulationMode::Compat, "85b800e91613b138"},
                      Pinned{"example1_single_cube", SimulationMode::Rules, "81dc43ad5ef2421b"},
                      Pinned{"example2_two_cubes", SimulationMode::Bullet, "059fd0d10b20a888"},
                      Pinned{"example2_two_cubes", SimulationMode::Compat, "32404d76cf6d4b86"},
                      Pinned{"example2_two_cubes", SimulationMode::Rules, "ac763547cc1d6a3d"},
                      Pinned{"example3_stacked_cubes", SimulationMode::Bullet, "756559c832064f55"},
                      Pinned{"example3_stacked_cubes", SimulationMode::Compat, "82a13e3c34644114"},
                      Pinned{"example3_stacked_cubes", SimulationMode::Rules, "063bc435ac222aa8"},
                      Pinned{"example4_two_spheres", SimulationMode::Bullet, "3edc75d11e77ea81"},
                      Pinned{"example4_two_spheres", SimulationMode::Compat, "ed2d72487f819b75"},
                      Pinned{"example4_two_spheres", SimulationMode::Rules, "40be062e5a617c64"},
                      Pinned{"misaligned_cubes", SimulationMode::Bullet, "7ef4d81fccd0b6cd"},
                      Pinned{"misaligned_cubes", SimulationMode::Compat, "c91a6158762e75ae"},
                      Pinned{"misaligned_cubes", SimulationMode::Rules, "67f34f8816947c11"},
                      Pinned{"sphere_bounces_back", SimulationMode::Bullet, "3bd4425e69a17beb"},
                      Pinned{"sphere_bounces_back", SimulationMode::Compat, "1eb51b7b54cbda14"},
                      Pinned{"sphere_bounces_back", SimulationMode::Rules, "81f04d1a2bb422fe"}),
    [](const ::testing::TestParamInfo<Pinned>& p) {
      return std::string(p.param.scenario) + "_" + std::string(toString(p.param.mode));
    });

}  // namespace
}  // namespace tabletop
