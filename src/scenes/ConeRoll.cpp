#include "scenes/ConeRoll.h"

#include <cmath>
#include <sstream>

#include "core/Quat.h"
#include "core/ShapeGeometry.h"
#include "scenario/ScenarioLoader.h"
#include "scenes/LawScenes.h"

namespace tabletop {
namespace {

// The body's geometry as the circle law needs it. Body frame: +y from
// base to top, origin at the centre of mass.
struct Roll {
  double half;    // rad, the half angle: between the axis and the slant side
  double apexY;   // m, the apex on the body's y axis
  Vec3 axis;      // world, the body's +y at the start
  Vec3 apex;      // world
  Vec3 centre;    // world, at the start
};

Roll roll(const RollCase& c) {
  const ShapeGeometry g = ShapeGeometry::cylinder(c.baseRadius, c.topRadius, c.height);
  const double below = g.centroidHeight();
  // The apex lies past the smaller end, where the slant side's line meets
  // the axis.
  const bool topSmaller = c.topRadius < c.baseRadius;
  const double big = topSmaller ? c.baseRadius : c.topRadius;
  const double small = topSmaller ? c.topRadius : c.baseRadius;
  const double reach = big * c.height / (big - small);  // from the larger end
  Roll r;
  r.half = std::atan((big - small) / c.height);
  r.apexY = topSmaller ? -below + reach : c.height - below - reach;
  // Lying with its slant side along +x from the apex: the axis runs from
  // the apex up at the half angle towards the larger end.
  const Vec3 towardBig{std::cos(r.half), std::sin(r.half), 0};
  r.axis = topSmaller ? Vec3{-towardBig.x, -towardBig.y, 0} : towardBig;
  const double x0 = c.support == "table" ? 0.0 : 3.0;
  r.apex = {x0, supportTop(c.support), 0};
  r.centre = {r.apex.x - r.axis.x * r.apexY, r.apex.y - r.axis.y * r.apexY, 0};
  return r;
}

}  // namespace

Vec3 rollApex(const RollCase& c) { return roll(c).apex; }

double rollSpin(const RollCase& c) { return -c.precession / std::tan(roll(c).half); }

Vec3 rollCentre(const RollCase& c, double t) {
  const Roll r = roll(c);
  const Vec3 arm = r.centre - r.apex;
  const double turn = c.precession * t, cs = std::cos(turn), sn = std::sin(turn);
  // Turned about +y: x' = x cos + z sin, z' = -x sin + z cos.
  return {r.apex.x + arm.x * cs + arm.z * sn, r.centre.y, r.apex.z - arm.x * sn + arm.z * cs};
}

Scenario rollScene(const RollCase& c) {
  const Roll r = roll(c);
  // The body's +y turned about z onto the axis.
  const double angle = std::atan2(-r.axis.x, r.axis.y);
  const Quat q = Quat::about({0, 0, 1}, angle);
  // Rolling: the spin along the slant side (+x), the centre moving as
  // w x (centre - apex).
  const double w = rollSpin(c);
  const Vec3 arm = r.centre - r.apex;
  const Vec3 v{0, -w * arm.z, w * arm.y};
  std::ostringstream text;
  text.precision(17);
  text << R"({"version": 1, "name": "roll", "table": {"size": [2.0, 2.0], "material": {"friction": 1}},
    "ground": {"material": {"friction": 1}}, "settings": {"timestep": )"
       << 1.0 / c.rate << R"(, "duration": )" << kRollDuration << R"(, "end_at_rest": false}, "entities": [)"
       << supportEntity(c.support) << R"({"name": "A", "shape": "cylinder", "size": [)" << c.baseRadius << ", "
       << c.topRadius << ", " << c.height << R"(], "position": [)" << r.centre.x << ", " << r.centre.y << ", "
       << r.centre.z << R"(], "orientation": {"quaternion": [)" << q.w << ", " << q.x << ", " << q.y << ", " << q.z
       << R"(]}, "mass": 1.0, "material": {"friction": 1}, "velocity": [)" << v.x << ", " << v.y << ", " << v.z
       << R"(], "spin": [)" << w << R"(, 0, 0]}], "script": []})";
  Scenario s = ScenarioLoader::loadText(text.str(), "roll.json");
  s.settings.timestep = 1.0 / c.rate;  // exactly, not as printed
  return s;
}

std::string describe(const RollCase& c) {
  std::ostringstream s;
  s << (c.topRadius == 0 || c.baseRadius == 0 ? "cone " : "truncated cone ") << c.baseRadius << " / " << c.topRadius
    << " x " << c.height << " on the " << c.support << ", precessing at " << c.precession << " rad/s, " << c.rate
    << " Hz";
  return s.str();
}

}  // namespace tabletop
