// The laws' scenes: the entity is last, on or over the support asked for
// (the slab standing on the floor); the pushed one starts where
// pushStart() says and is pushed once, the dropped one hangs kDropHeight
// above where it touches.

#include "scenes/LawScenes.h"

#include <cmath>
#include <optional>

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

// The spin law's closed forms worked by hand: a cube's corners at a / sqrt 2
// with k^2 = a^2 / 6, a box's at half its diagonal with k^2 = (w^2 + d^2) / 12,
// a cylinder's rim at r with k^2 = r^2 / 2; none for a sphere.
TEST(LawScenes, GivesTheSpinLawsClosedForm) {
  const double g = 9.81, mu = 0.3, w0 = -4.0;
  const struct {
    const char* shape;
    const char* size;
    double rho, k2;
  } shapes[] = {{"cube", "0.2", 0.1 * std::sqrt(2.0), 0.04 / 6.0},
                {"box", "[0.3, 0.1, 0.1]", std::hypot(0.15, 0.05), (0.09 + 0.01) / 12.0},
                {"cylinder", "[0.06, 0.06, 0.2]", 0.06, 0.0036 / 2.0}};
  for (const auto& s : shapes) {
    PushCase c{s.shape, s.size, "table", 0.0, 60.0, mu};
    c.spin = w0;
    const std::optional<SpinLaw> law = spinLaw(c);
    ASSERT_TRUE(law) << s.shape;
    EXPECT_NEAR(law->rho, s.rho, 1e-12) << s.shape;
    EXPECT_NEAR(law->angle, -w0 * w0 / (2.0 * mu * g * s.rho / s.k2), 1e-12) << s.shape;
  }
  PushCase ball{"sphere", "0.05", "table", 0.0, 60.0, mu};
  ball.spin = w0;
  EXPECT_FALSE(spinLaw(ball));
}

}  // namespace
}  // namespace tabletop
