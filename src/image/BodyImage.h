#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace tabletop {

/// What each pixel of a frame shows beside its colour, as PyBullet's
/// getCameraImage and MuJoCo's Renderer give it: which body (its label)
/// and how far from the camera along its view axis, metres (infinity where
/// nothing is). Top row first, as Image.
struct BodyImage {
  /// Labels that name no entity (an entity's label is its index in the
  /// scenario, from 0).
  static constexpr std::int32_t kNothing = -1;
  static constexpr std::int32_t kTable = -2;
  static constexpr std::int32_t kGround = -3;

  int width = 0;
  int height = 0;
  std::vector<std::int32_t> labels;  ///< width * height
  std::vector<float> depth;          ///< width * height, metres

  BodyImage() = default;
  BodyImage(int w, int h)
      : width(w),
        height(h),
        labels(static_cast<std::size_t>(w) * h, kNothing),
        depth(static_cast<std::size_t>(w) * h, std::numeric_limits<float>::infinity()) {}
};

}  // namespace tabletop
