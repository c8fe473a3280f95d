#include "scenes/LawScenes.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "core/Angle.h"
#include "scenario/ScenarioLoader.h"

namespace tabletop {
namespace {

// The slab on the floor, as a scene's first entity.
constexpr const char* kSlab = R"({"name": "Base", "shape": "box", "size": [1.6, 0.1, 1.6], "position": [3, 0],
  "on": "ground", "mass": 100, "material": {"friction": 1, "restitution": 1}}, )";
// The drum, a 100 kg cylinder standing on the floor there: a support whose
// top is a disc.
constexpr const char* kDrum = R"({"name": "Base", "shape": "cylinder", "size": [0.8, 0.8, 0.1], "position": [3, 0],
  "on": "ground", "mass": 100, "material": {"friction": 1, "restitution": 1}}, )";
constexpr double kBaseTop = 0.1;   // m, the slab's and the drum's top
constexpr double kTableTop = 0.75;  // m, the default table's

}  // namespace

const char* supportEntity(const std::string& support) {
  return support == "slab" ? kSlab : support == "drum" ? kDrum : "";
}

double supportTop(const std::string& support) {
  return support == "table" ? kTableTop : support == "ground" ? 0.0 : kBaseTop;
}

std::pair<double, double> pushStart(const PushCase& c) {
  if (c.support == "table") return {-0.3 * std::cos(convertAngle(c.angle)), 0.3 * std::sin(convertAngle(c.angle))};
  return {3.0, 0.0};
}

Scenario pushScene(const PushCase& c) {
  const auto [x0, z0] = pushStart(c);
  const bool base = c.support == "slab" || c.support == "drum";
  std::ostringstream text;
  text.precision(17);
  text << R"({"version": 1, "name": "push", "table": {"size": [2.0, 2.0], "material": {"friction": 1}},
    "ground": {"material": {"friction": 1}}, "settings": {"timestep": )"
       << 1.0 / c.rate << R"(, "duration": 3}, "entities": [)";
  text << supportEntity(c.support);
  text << R"({"name": "A", "shape": ")" << c.shape << R"(", "size": )" << c.size << R"(, "position": [)" << x0
       << ", " << z0 << R"(], "on": ")" << (base ? "Base" : c.support) << R"(", "mass": )" << kPushedMass
       << R"(, "material": {"friction": )" << c.friction << R"(, "rolling_friction": )" << c.rollingFriction
       << R"(}, "spin": [0, )" << c.spin << ", 0]";
  if (c.lying != PushCase::Lying::Upright) {
    // The body's y axis turned a right angle about y x u onto u, the level
    // direction across the push, (sin a, 0, cos a), or along it.
    const double a = convertAngle(c.angle);
    const double ux = c.lying == PushCase::Lying::Across ? std::sin(a) : std::cos(a);
    const double uz = c.lying == PushCase::Lying::Across ? std::cos(a) : -std::sin(a);
    text << R"(, "orientation": {"axis": [)" << uz << ", 0, " << -ux << R"(], "angle": 90})";
  }
  text << R"(}], "script": [)";
  if (c.step > 0 || c.impulse > 0) {
    text << R"({"push": {"entity": "A", "angle": )" << c.angle << ", ";
    if (c.step > 0) {
      text << R"("step": )" << c.step;
    } else {
      text << R"("impulse": )" << c.impulse;
      if (c.at) text << R"(, "at": [)" << c.at->x << ", " << c.at->y << ", " << c.at->z << "]";
    }
    text << "}}";
  }
  text << "]}";
  return ScenarioLoader::loadText(text.str(), "push.json");
}

std::optional<SpinLaw> spinLaw(const PushCase& c) {
  const Scenario s = pushScene(c);
  const ShapeGeometry& g = s.entities.back().geometry;
  double rho = 0;
  switch (g.kind()) {
    case ShapeKind::Sphere: return std::nullopt;
    case ShapeKind::Cylinder: rho = g.radius(); break;
    case ShapeKind::Cube:
    case ShapeKind::SolidBox: rho = std::hypot(g.halfExtents().x, g.halfExtents().z); break;
  }
  const double k2 = g.inertia(1.0).y;
  const double alpha = c.friction * s.settings.gravity * rho / k2;
  return SpinLaw{rho, c.spin * std::abs(c.spin) / (2.0 * alpha)};
}

Scenario rideScene(const RideCase& c) {
  const double x0 = c.support == "table" ? -0.4 : 3.0;
  std::ostringstream text;
  text.precision(17);
  text << R"({"version": 1, "name": "ride", "table": {"size": [2.4, 2.4], "material": {"friction": )" << c.mu1
       << R"(}}, "ground": {"material": {"friction": )" << c.mu1 << R"(}}, "settings": {"timestep": )" << 1.0 / c.rate
       << R"(, "duration": 2}, "entities": [)"
       << R"({"name": "A", "shape": "cube", "size": )" << c.sizeA << R"(, "position": [)" << x0 << R"(, 0], "on": ")"
       << c.support << R"(", "mass": )" << c.massA << R"(, "material": {"friction": 1}}, )"
       << R"({"name": "B", "shape": ")" << c.shapeB << R"(", "size": )" << c.sizeB << R"(, "position": [)" << x0
       << R"(, 0], "on": "A", "mass": )" << c.massB << R"(, "material": {"friction": )" << c.mu2 << "}}], "
       << R"("script": [{"push": {"entity": "A", "angle": )" << c.angle << R"(, "impulse": )" << c.massA * c.speed
       << "}}]}";
  return ScenarioLoader::loadText(text.str(), "ride.json");
}

std::string describe(const RideCase& c) {
  std::ostringstream s;
  s << c.massB << " kg " << c.shapeB << " " << c.sizeB << " on " << c.massA << " kg, mu " << c.mu1 << " / " << c.mu2 << ", on the " << c.support << ", at "
    << c.angle << " deg, " << c.rate << " Hz";
  return s.str();
}

std::string describe(const PushCase& c) {
  std::ostringstream s;
  s << c.shape << " " << c.size;
  if (c.lying != PushCase::Lying::Upright) s << (c.lying == PushCase::Lying::Across ? " lying across" : " lying along");
  s << " on the " << c.support << ", ";
  if (c.spin != 0) s << "spun at " << c.spin << " rad/s";
  else s << "at " << c.angle << " deg";
  s << ", " << c.rate << " Hz";
  return s.str();
}

double dropTouchHeight(const DropCase& c) {
  return supportTop(c.support) + c.below;
}

double dropHeight(const DropCase& c, double gravity, double t) {
  const double rest = dropTouchHeight(c), t0 = std::sqrt(2.0 * kDropHeight / gravity);
  if (t <= t0) return rest + kDropHeight - 0.5 * gravity * t * t;
  const double up = c.restitution * gravity * t0, since = t - t0;
  return up > 0 ? rest + up * since - 0.5 * gravity * since * since : rest;
}

double dropEnd(const DropCase& c, double gravity) {
  const double t0 = std::sqrt(2.0 * kDropHeight / gravity), up = c.restitution * gravity * t0;
  return t0 + (up > 0 ? 0.98 * 2.0 * up / gravity : 0.3);
}

Scenario dropScene(const DropCase& c) {
  std::ostringstream text;
  text.precision(17);
  text << R"({"version": 1, "name": "drop", "ground": {"material": {"restitution": 1}},
    "table": {"material": {"restitution": 1}}, "settings": {"timestep": )"
       << 1.0 / c.rate << R"(, "duration": 1.2, "end_at_rest": false}, "entities": [)";
  text << supportEntity(c.support);
  text << R"({"name": "A", "shape": ")" << c.shape << R"(", "size": )" << c.size << R"(, "position": [)"
       << (c.support == "table" ? 0.0 : 3.0) << ", " << dropTouchHeight(c) + kDropHeight
       << R"(, 0.0], "mass": 1.0, "material": {"restitution": )" << c.restitution << "}}]}";
  return ScenarioLoader::loadText(text.str(), "drop.json");
}

std::string describe(const DropCase& c) {
  std::ostringstream s;
  s << c.shape << " " << c.size << " on the " << c.support << ", e " << c.restitution << ", " << c.rate << " Hz";
  return s.str();
}

}  // namespace tabletop
