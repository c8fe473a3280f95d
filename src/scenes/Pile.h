#pragma once

#include <cstdint>

#include "scenario/Scenario.h"

namespace tabletop {

/// The pile scene of `bench --piles`: `n` mixed bodies (cubes, spheres,
/// boxes and standing cylinders, in turn) with sizes, masses and materials
/// drawn from a seed, placed in a grid kGap apart (between their bounding
/// spheres) from kDropHeight above a table made to fit, and dropped at
/// once. A grid layer holds at most kLayerSide x kLayerSide bodies; more
/// go into layers above. Runs kSettle + kWindow s at the defaults but at
/// 60 Hz, not until rest. The same seed gives the same pile everywhere
/// (std::mt19937_64's raw words, as RandomScene).
class Pile {
 public:
  static constexpr double kGap = 0.1;         ///< m, between neighbours' bounding spheres
  static constexpr double kDropHeight = 0.1;  ///< m, the lowest layer's bottom above the top
  static constexpr double kLargest = 0.08;    ///< m, the longest side or diameter a body gets
  static constexpr double kSmallest = 0.03;   ///< m
  static constexpr double kSettle = 1.5;      ///< s, the drop, before the settled window
  static constexpr double kWindow = 1.0;      ///< s, the settled window
  static constexpr double kRate = 60.0;       ///< Hz
  static constexpr int kLayerSide = 16;       ///< bodies along a layer's side, at most

  /// The pile of `n` bodies (n >= 1) for `seed`, named "pile_N".
  static Scenario make(int n, std::uint64_t seed = 1);
  /// m: centre to centre in the grid.
  static double pitch();
};

}  // namespace tabletop
