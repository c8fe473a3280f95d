// FlatFour: of the points a pass offers a manifold, the four spanning the
// widest area where they lie flat, the four it held on a tie; nothing
// chosen where they do not lie flat or are four or fewer.

#include "physics/collision/FlatFour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

#include <btBulletCollisionCommon.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

btManifoldPoint pointAt(double x, double z, double depth = -1e-9) {
  const btVector3 at(x, 0, z);
  return btManifoldPoint(at, at, btVector3(0, 1, 0), depth);
}

// A manifold holding `held` (x, z) places, offered `offered` in one pass.
struct Pass {
  btCollisionObject a, b;
  btPersistentManifold manifold{&a, &b, 0, 0.02, 0.02};
  OfferedPoints offered;
  const OfferedPoints::Offers& offer(std::initializer_list<std::array<double, 2>> held,
                                     std::initializer_list<btManifoldPoint> offeredPoints) {
    for (const auto& [x, z] : held) manifold.addManifoldPoint(pointAt(x, z));
    offered.clear();
    for (const btManifoldPoint& p : offeredPoints) offered.offer(manifold, p);
    return offered.offers().front();
  }
};

std::array<int, 4> sorted(std::array<int, 4> chosen) {
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

TEST(FlatFour, SpannedAreaIsTwiceAConvexQuadrilateralsAreaInAnyOrder) {
  const btVector3 a(0, 0, 0), b(0.08, 0, 0), c(0.08, 0, 0.1), d(0, 0, 0.1);
  EXPECT_NEAR(spannedArea(a, b, c, d), 2 * 0.08 * 0.1, 1e-15);
  EXPECT_NEAR(spannedArea(a, c, b, d), 2 * 0.08 * 0.1, 1e-15);
  EXPECT_NEAR(spannedArea(a, b, d, c), 2 * 0.08 * 0.1, 1e-15);
}

// Aligned faces share edges, and rounding cuts them anywhere: a point on
// an edge is never among the widest four of a rectangle's corners,
// wherever it is offered.
TEST(FlatFour, ARectanglesCornersBeatAPointOnItsEdge) {
  for (int at = 0; at < 5; ++at) {
    Pass pass;
    btManifoldPoint points[5] = {pointAt(0.07, -0.05), pointAt(0.15, -0.05), pointAt(0.15, 0.05),
                                 pointAt(0.07, 0.05), pointAt(0.11, -0.05, -1e-10)};
    std::rotate(points, points + 4, points + 5);  // the edge point first ...
    std::rotate(points, points + at, points + 5);  // ... then at each place
    const auto& offers = pass.offer({}, {points[0], points[1], points[2], points[3], points[4]});
    std::array<int, 4> chosen;
    ASSERT_TRUE(widestFour(offers, chosen)) << at;
    for (const int k : chosen) EXPECT_NE(offers.points[k].m_localPointA.x(), 0.11) << at;
  }
}

// The octagon where two equal squares meet turned 45 degrees holds two
// inscribed squares of one area: the four the manifold held stay.
TEST(FlatFour, OfTwoEqualFoursTheOneHeldStays) {
  const double r = 0.05;
  btManifoldPoint corners[8];
  for (int k = 0; k < 8; ++k) {
    const double angle = k * M_PI / 4;
    corners[k] = pointAt(r * std::cos(angle), r * std::sin(angle));
  }
  for (const int first : {0, 1}) {
    Pass pass;
    const double c0 = std::cos(first * M_PI / 4), s0 = std::sin(first * M_PI / 4);
    const double c1 = std::cos((first + 2) * M_PI / 4), s1 = std::sin((first + 2) * M_PI / 4);
    const auto& offers = pass.offer({{r * c0, r * s0}, {r * c1, r * s1}, {-r * c0, -r * s0}, {-r * c1, -r * s1}},
                                    {corners[0], corners[1], corners[2], corners[3], corners[4], corners[5],
                                     corners[6], corners[7]});
    std::array<int, 4> chosen;
    ASSERT_TRUE(widestFour(offers, chosen));
    const std::array<int, 4> held = {first, first + 2, first + 4, first + 6};
    EXPECT_EQ(sorted(chosen), held) << "held the square from corner " << first;
  }
}

TEST(FlatFour, NothingIsChosenFromFourOrFewerOrFromPointsNotFlat) {
  Pass four;
  std::array<int, 4> chosen;
  EXPECT_FALSE(widestFour(four.offer({}, {pointAt(0, 0), pointAt(1, 0), pointAt(1, 1), pointAt(0, 1)}), chosen));
  // Depths 20 um apart: a tipping face, whose deepest points hold the
  // bodies apart, is Bullet's to choose.
  Pass tipping;
  EXPECT_FALSE(widestFour(tipping.offer({}, {pointAt(0, 0), pointAt(1, 0), pointAt(1, 1), pointAt(0, 1),
                                              pointAt(0.5, 1.2, -2e-5)}),
                          chosen));
  Pass flat;
  EXPECT_TRUE(widestFour(flat.offer({}, {pointAt(0, 0), pointAt(1, 0), pointAt(1, 1), pointAt(0, 1),
                                          pointAt(0.5, 1.2, -9e-6)}),
                         chosen));
}

}  // namespace
}  // namespace tabletop
