// Shrinking an image averages each square of pixels (the renderer's
// anti-aliasing), rounded to the nearest level.

#include <gtest/gtest.h>

#include "image/Image.h"

namespace tabletop {
namespace {

TEST(Image, ShrunkAveragesEachSquare) {
  Image big(4, 2);
  // Left square: 0, 255, 255, 255 in red -> 191.25 -> 191; right square all 10.
  const int reds[2][4] = {{0, 255, 10, 10}, {255, 255, 10, 10}};
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 4; ++column) {
      big.rgb[(row * 4 + column) * 3] = static_cast<std::uint8_t>(reds[row][column]);
      big.rgb[(row * 4 + column) * 3 + 1] = 2;  // 2 everywhere stays 2
      big.rgb[(row * 4 + column) * 3 + 2] = static_cast<std::uint8_t>(row);  // 0, 0, 1, 1 -> 0.5 -> 1
    }
  }
  const Image small = big.shrunk(2);
  ASSERT_EQ(small.width, 2);
  ASSERT_EQ(small.height, 1);
  EXPECT_EQ(small.at(0, 0).r, 191);
  EXPECT_EQ(small.at(1, 0).r, 10);
  EXPECT_EQ(small.at(0, 0).g, 2);
  EXPECT_EQ(small.at(1, 0).b, 1);
  const Image same = big.shrunk(1);
  EXPECT_EQ(same.rgb, big.rgb);
}

}  // namespace
}  // namespace tabletop
