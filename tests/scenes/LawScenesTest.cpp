// The laws' scenes: the entity is last, on or over the support asked for
// (the slab standing on the floor); the pushed one starts where
// pushStart() says and is pushed once, the dropped one hangs kDropHeight
// above where it touches.

#include "scenes/LawScenes.h"

#include <gtest/gtest.h>

#include "core/Support.h"

namespace tabletop {
namespace {

TEST(LawScenes, StandsThePushedEntityOnItsSupport) {
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

TEST(LawScenes, HangsTheDroppedEntityAboveItsSupport) {
  for (const char* support : {"table", "ground", "slab"}) {
    const DropCase c{"cube", "0.1", 0.05, support, 0.5, 240.0};
    const Scenario s = dropScene(c);
    ASSERT_EQ(s.entities.size(), std::string(support) == "slab" ? 2u : 1u) << support;
    const double top = std::string(support) == "table" ? 0.75 : std::string(support) == "slab" ? 0.1 : 0.0;
    EXPECT_NEAR(dropTouchHeight(c), top + 0.05, 1e-12) << support;
    EXPECT_NEAR(s.entities.back().position.y, top + 0.05 + kDropHeight, 1e-12) << support;
    EXPECT_TRUE(s.entities.back().on.isNone()) << support;
  }
}

}  // namespace
}  // namespace tabletop
