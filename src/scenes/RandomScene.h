#pragma once

#include <cstdint>

#include "scenario/Scenario.h"

namespace tabletop {

/// Randomised robustness (hard case 9): a scene of two to five bodies on
/// the report's table and a sequence of pushes, all drawn from one seed.
/// The same seed gives the same scene on every machine: the draws come
/// from std::mt19937_64, whose sequence the C++ standard fixes, turned into
/// numbers by this class alone (not by the library's distributions, which
/// differ between standard libraries).
///
/// What is drawn, in SI units:
///  - each body: a cube, sphere, box or cylinder (a cone when its radii
///    differ), 2-20 cm across, 0.05-5 kg (log-uniform, so mass ratios up
///    to 100), friction 0-1, restitution 0-0.9, any yaw; placed on the
///    table clear of the others, or on an earlier cube, box or cylinder
///    (a stack) when there is room for it there;
///  - one to four pushes at 0-0.6 s, on a random face (a random angle for
///    spheres and cylinders), each an impulse giving its body 0.1-5 m/s,
///    enough to send bodies off the table and onto the floor.
/// Runs kDuration in full physics at the project's default settings (not
/// until rest).
class RandomScene {
 public:
  static constexpr double kDuration = 1.0;  ///< s
  static constexpr int kMinBodies = 2;
  static constexpr int kMaxBodies = 5;

  /// The scene for `seed`, named "random_SEED".
  static Scenario make(std::uint64_t seed);
};

}  // namespace tabletop
