// The pushed entity's scene: the entity is last, stands on the support
// asked for (the slab standing on the floor), starts where pushStart()
// says, and is pushed once at the angle asked.

#include "scenes/PushScene.h"

#include <gtest/gtest.h>

#include "core/Support.h"

namespace tabletop {
namespace {

TEST(PushScene, StandsTheEntityOnItsSupport) {
  for (const char* support : {"table", "ground", "slab"}) {
    PushCase c{"cylinder", "[0.05, 0.03, 0.1]", support, 77.0, 60.0};
    c.impulse = 2.4;
    const Scenario s = pushScene(c);
    ASSERT_EQ(s.entities.size(), std::string(support) == "slab" ? 2u : 1u) << support;
    const EntitySpec& a = s.entities.back();
    EXPECT_EQ(a.name, "A");
    EXPECT_EQ(a.on, std::string(support) == "slab" ? Support::entity("Base")
                    : std::string(support) == "table" ? Support::table()
                                                       : Support::ground());
    const auto [x0, z0] = pushStart(c);
    EXPECT_DOUBLE_EQ(a.position.x, x0);
    EXPECT_DOUBLE_EQ(a.position.z, z0);
    EXPECT_DOUBLE_EQ(s.settings.timestep, 1.0 / 60.0);
    EXPECT_EQ(s.script.size(), 1u);
  }
}

}  // namespace
}  // namespace tabletop
