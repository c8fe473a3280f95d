#pragma once

#include <string>
#include <utility>

#include "scenario/Scenario.h"

namespace tabletop {

/// One entity pushed across a support, the scene of the sliding, rolling
/// and step laws (tests/sim/SlideTest, bench --laws): 1.5 kg, pushed at a
/// world angle from the table's centre (0.3 m back from it), or 3 m from
/// it on the floor or on a 100 kg slab resting there, towards open space.
/// The slab (1.6 x 0.1 x 1.6 m, floor friction 1) is held by the floor
/// against the slider's friction: it does not move. Table and floor
/// friction are 1, so the entity's own coefficients are the contact's.
struct PushCase {
  std::string shape;    ///< scenario "shape"
  std::string size;     ///< scenario "size", as JSON
  std::string support;  ///< "table", "ground" or "slab"
  double angle = 0;     ///< degrees, the push's world angle
  double rate = 60;     ///< Hz
  double friction = 0.25;
  double rollingFriction = 0;  ///< m
  double impulse = 0;          ///< N s, or else
  double step = 0;             ///< m, a push by step
};

inline constexpr double kPushedMass = 1.5;  ///< kg

/// The scene, the pushed entity last (named "A"), for 3 s.
Scenario pushScene(const PushCase& c);

/// Where the pushed entity starts on its support, x and z, m.
std::pair<double, double> pushStart(const PushCase& c);

/// "cube 0.1 on the table, at 30 deg, 60 Hz".
std::string describe(const PushCase& c);

}  // namespace tabletop
