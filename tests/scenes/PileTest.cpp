// The pile scene of bench --piles: deterministic for a seed, the mix and
// count asked for, every body clear of the others and above the table,
// and dropped: it falls onto the table and stays on it.

#include "scenes/Pile.h"

#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "physics/World.h"
#include "sim/SceneBuilder.h"
#include "support/RunScene.h"

namespace tabletop {
namespace {

// Radius of a sphere around the centre that holds the body, m.
double bound(const ShapeGeometry& g) {
  const std::vector<double> s = g.sizes();
  switch (g.kind()) {
    case ShapeKind::Cube: return 0.5 * std::sqrt(3.0) * s[0];
    case ShapeKind::Sphere: return s[0];
    case ShapeKind::SolidBox: return 0.5 * std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    case ShapeKind::Cylinder: return std::hypot(std::max(s[0], s[1]), 0.5 * s[2]);
  }
  return 0.0;
}

TEST(Pile, TheSameSeedGivesTheSamePileAndAnotherSeedAnother) {
  const Scenario a = Pile::make(40, 7), b = Pile::make(40, 7), c = Pile::make(40, 8);
  ASSERT_EQ(a.entities.size(), b.entities.size());
  bool differs = false;
  for (std::size_t i = 0; i < a.entities.size(); ++i) {
    EXPECT_EQ(a.entities[i].geometry.sizes(), b.entities[i].geometry.sizes());
    EXPECT_EQ(a.entities[i].mass, b.entities[i].mass);
    EXPECT_EQ(a.entities[i].position.y, b.entities[i].position.y);
    differs |= a.entities[i].mass != c.entities[i].mass;
  }
  EXPECT_TRUE(differs);
}

// Every count gets exactly its bodies, the four kinds in equal shares (one
// apart at most), sizes and masses varied and in their ranges.
TEST(Pile, HasTheCountAndMixAsked) {
  for (int n : {1, 5, 100, 257, 1000}) {
    const Scenario s = Pile::make(n);
    ASSERT_EQ(static_cast<int>(s.entities.size()), n);
    std::map<ShapeKind, int> kinds;
    double lightest = 1e9, heaviest = 0;
    for (const EntitySpec& e : s.entities) {
      ++kinds[e.geometry.kind()];
      lightest = std::min(lightest, e.mass);
      heaviest = std::max(heaviest, e.mass);
      for (double size : e.geometry.sizes()) EXPECT_LE(size, Pile::kLargest + 1e-12) << e.name;
      EXPECT_LE(bound(e.geometry), 0.5 * std::sqrt(3.0) * Pile::kLargest + 1e-12) << e.name;
      if (e.geometry.kind() == ShapeKind::Cylinder) {
        EXPECT_EQ(e.geometry.sizes()[0], e.geometry.sizes()[1]);
      }
    }
    for (const auto& [kind, count] : kinds) EXPECT_LE(std::abs(count - n / 4), 1) << n;
    if (n >= 4) {
      EXPECT_EQ(kinds.size(), 4u) << n;
    }
    if (n >= 100) {
      EXPECT_GT(heaviest / lightest, 5.0) << n;
    }
  }
}

// Bounding spheres kGap apart, every body over the top and above it.
TEST(Pile, StartsClearOfEachOtherAndAboveTheTable) {
  const Scenario s = Pile::make(300);
  for (std::size_t i = 0; i < s.entities.size(); ++i) {
    const EntitySpec& e = s.entities[i];
    EXPECT_TRUE(e.on.isNone()) << e.name;
    EXPECT_GE(e.position.y - bound(e.geometry), s.table.height + Pile::kDropHeight - 1e-12) << e.name;
    EXPECT_LT(std::abs(e.position.x) + bound(e.geometry), 0.5 * s.table.width) << e.name;
    EXPECT_LT(std::abs(e.position.z) + bound(e.geometry), 0.5 * s.table.depth) << e.name;
    for (std::size_t j = 0; j < i; ++j) {
      const Vec3 d = e.position - s.entities[j].position;
      EXPECT_GE(d.length() - bound(e.geometry) - bound(s.entities[j].geometry), Pile::kGap - 1e-9) << e.name;
    }
  }
  EXPECT_TRUE(buildWorld(s, s.settings)->overlaps(0.0).empty());
}

// Dropped, a small pile lands: every body ends lower than it started,
// resting within a body's size of the top.
TEST(Pile, FallsOntoTheTable) {
  const Scenario s = Pile::make(8);
  const RunResult r = test::runScene(s);
  ASSERT_TRUE(r.complete);
  for (std::size_t i = 0; i < s.entities.size(); ++i) {
    EXPECT_LT(r.entities[i].position.y, s.entities[i].position.y - 0.05) << s.entities[i].name;
    EXPECT_LT(r.entities[i].position.y, s.table.height + 2 * Pile::kLargest) << s.entities[i].name;
    EXPECT_GT(r.entities[i].position.y, s.table.height) << s.entities[i].name;
  }
}

}  // namespace
}  // namespace tabletop
