#include "core/Boundary.h"

#include <gtest/gtest.h>

namespace tabletop {
namespace {

// Report 3.2, worked by hand: a cube of side 0.2 m at (1, 2, 3).
TEST(Boundary, CubeFacesAreHalfASideFromTheCentre) {
  const Boundary b = cubeBoundary({1.0, 2.0, 3.0}, 0.2);
  EXPECT_DOUBLE_EQ(b.left, 0.9);
  EXPECT_DOUBLE_EQ(b.right, 1.1);
  EXPECT_DOUBLE_EQ(b.top, 2.1);
  EXPECT_DOUBLE_EQ(b.bottom, 1.9);
  EXPECT_DOUBLE_EQ(b.far, 2.9);
  EXPECT_DOUBLE_EQ(b.near, 3.1);
}

TEST(Boundary, ExtentsEqualTheSide) {
  const Boundary b = cubeBoundary({-0.3, 0.8, 0.05}, 0.07);
  EXPECT_NEAR(b.right - b.left, 0.07, 1e-15);
  EXPECT_NEAR(b.top - b.bottom, 0.07, 1e-15);
  EXPECT_NEAR(b.near - b.far, 0.07, 1e-15);
}

}  // namespace
}  // namespace tabletop
