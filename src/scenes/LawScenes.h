#pragma once

#include <optional>
#include <string>
#include <utility>

#include "scenario/Scenario.h"

namespace tabletop {

/// The scenes of the laws every shape on every support must follow
/// (tests/physics/laws/SlideTest and RestitutionTest, bench --laws). The supports:
/// "table", "ground", "slab", a 100 kg box 1.6 x 0.1 x 1.6 m resting on
/// the floor 3 m from the table's centre (floor friction 1), and "drum", a
/// 100 kg cylinder 0.8 m in radius and 0.1 m high standing there.
inline constexpr const char* kLawSupports[] = {"table", "ground", "slab", "drum"};

/// The entity a support needs first in a law's scene, as JSON followed by
/// ", " (the slab's or the drum's, named "Base"; "" for the table and the
/// floor).
const char* supportEntity(const std::string& support);

/// The support's top, m.
double supportTop(const std::string& support);

/// One entity pushed across a support, the scene of the sliding, rolling,
/// step and spinning laws: 1.5 kg, pushed (or spun) at a
/// world angle from the table's centre (0.3 m back from it), or 3 m from
/// it on the floor, or on the slab or the drum resting there, towards open
/// space. The floor (friction 1) holds either against the slider's
/// friction: it does not move. Table and floor
/// friction are 1, so the entity's own coefficients are the contact's.
struct PushCase {
  std::string shape;    ///< scenario "shape"
  std::string size;     ///< scenario "size", as JSON
  std::string support;  ///< one of kLawSupports
  double angle = 0;     ///< degrees, the push's world angle
  double rate = 60;     ///< Hz
  double friction = 0.25;
  double rollingFriction = 0;  ///< m
  double impulse = 0;          ///< N s, or else
  double step = 0;             ///< m, a push by step (neither: no push)
  double spin = 0;             ///< rad/s about the vertical at the start
  /// Where the push acts, m in the body's frame (level with its centre);
  /// none: through the centre.
  std::optional<Vec3> at = std::nullopt;
  /// A cylinder laid on its side, its axis level and across the push (it
  /// rolls) or along it (it slides); else upright.
  enum class Lying { Upright, Across, Along } lying = Lying::Upright;
};

inline constexpr double kPushedMass = 1.5;  ///< kg

/// The scene, the pushed entity last (named "A"), for 3 s.
Scenario pushScene(const PushCase& c);

/// Where the pushed entity starts on its support, x and z, m.
std::pair<double, double> pushStart(const PushCase& c);

/// "cube 0.1 on the table, at 30 deg, 60 Hz".
std::string describe(const PushCase& c);

/// The spinning law's closed form for a case with a spin: a body standing
/// on a face or its base is slowed by the friction of its contact points,
/// mu m g at a distance rho from the axis (the corners of a box's face, the
/// rim points of a cylinder's base), at alpha = mu g rho / k^2
/// (k^2 = I / m about the vertical). It turns w0 |w0| / (2 alpha) and stops
/// where it stands.
///
/// rho is the model's, not a pressed patch's: a uniformly pressed square
/// face would resist at 0.383 of its edge (its area's mean distance from
/// the centre), not 0.707, and turn 1.85 times as far
/// (docs/bullet-corrections.md).
struct SpinLaw {
  double rho = 0;    ///< m
  double angle = 0;  ///< rad, the turn
};
/// Nothing for a sphere, which has no face to stand on.
std::optional<SpinLaw> spinLaw(const PushCase& c);

/// A cube carrying a rider (a smaller cube, or any shape standing on its
/// base), the cube pushed, the scene of the riding law: on the table (from
/// 0.4 m behind its centre) or on the floor (3 m from the table). Table and
/// floor friction are mu1, A's 1, so A slides on its support at mu1 and B
/// on A at mu2, B's own.
struct RideCase {
  std::string support;  ///< "table" or "ground"
  double massA = 2, massB = 0.5;  ///< kg
  double sizeA = 0.2;             ///< m, the cube's edge
  std::string shapeB = "cube";    ///< the rider's scenario "shape"
  std::string sizeB = "0.1";      ///< and "size", as JSON
  double mu1 = 0.6, mu2 = 0.3;
  double speed = 0.6;  ///< m/s, A's after the push
  double angle = 0;    ///< degrees, the push's world angle
  double rate = 60;    ///< Hz
};

/// The scene, A then B, for 2 s.
Scenario rideScene(const RideCase& c);

/// "0.5 kg on 2 kg, mu 0.6 / 0.3, on the table, at 37 deg, 60 Hz".
std::string describe(const RideCase& c);

/// One 1 kg entity dropped from kDropHeight above its support, upright,
/// the scene of the bouncing law: on the table at its centre, on the floor
/// 3 m from it, or on the slab or the drum there. Every support's restitution is 1, so
/// the entity's own is the contact's.
struct DropCase {
  std::string shape;       ///< scenario "shape"
  std::string size;        ///< scenario "size", as JSON
  double below = 0;        ///< m, its centre of mass above its lowest point
  std::string support;     ///< one of kLawSupports
  double restitution = 0;
  double rate = 60;        ///< Hz
};

inline constexpr double kDropHeight = 0.3;  ///< m, from touch

/// The scene, the dropped entity last (named "A"), for 1.2 s.
Scenario dropScene(const DropCase& c);

/// The height of the dropped entity's centre when it touches its support, m.
double dropTouchHeight(const DropCase& c);

/// The closed form of the drop, the centre's height at time t (s): free
/// fall until t0 = sqrt(2 h / g), then a rise at e v, v = g t0, until it
/// lands again at t0 + 2 e v / g (at rest on the support when e = 0).
double dropHeight(const DropCase& c, double gravity, double t);

/// When the closed form stops holding: just before the second landing
/// (98% of the flight), or 0.3 s past the first when e = 0.
double dropEnd(const DropCase& c, double gravity);

std::string describe(const DropCase& c);

}  // namespace tabletop
