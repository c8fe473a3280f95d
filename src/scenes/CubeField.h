#pragma once

#include "scenario/Scenario.h"

namespace tabletop {

/// The scale scene: `n` cubes (0.1 m, 0.5 kg) in a square grid at
/// kPitch on a table just large enough for them, every other column pushed
/// +X (on its Left face) by a step longer than the gap, so pushed cubes
/// strike the next column and hand their motion on. It runs a fixed
/// kDuration at the project's default settings, not until rest, so every
/// size takes the same number of steps.
class CubeField {
 public:
  static constexpr double kSide = 0.1;      ///< m
  static constexpr double kPitch = 0.25;    ///< m, centre to centre
  static constexpr double kStep = 0.2;      ///< m, the push: longer than the 0.15 m gap
  static constexpr double kDuration = 0.5;  ///< s

  /// The scene with `n` cubes (n >= 1), named "cube_field_N".
  static Scenario make(int n);
};

}  // namespace tabletop
