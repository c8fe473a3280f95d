#include "scenario/ScenarioParts.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/DirectionDef.h"
#include "core/EnumNames.h"
#include "core/Text.h"
#include "scenario/Orientation.h"
#include "scenario/ScenarioLoader.h"

namespace tabletop::parts {

using namespace fields;
using namespace ranges;

namespace {

Colour readColour(Fields& parent, const std::string& key, Colour c) {
  const json* v = parent.get(key, false);
  if (!v) return c;
  const std::vector<double> rgb = parent.numbers(*v, parent.at(key), 3, 3, kNonNegative);
  if (rgb.size() != 3) return c;
  for (std::size_t i = 0; i < 3; ++i) {
    if (rgb[i] > 255.0 || rgb[i] != std::floor(rgb[i])) {
      parent.fail(parent.at(key) + "/" + std::to_string(i),
                  "expected an integer from 0 to 255, got " + shown((*v)[i]));
      return c;
    }
  }
  return {static_cast<int>(rgb[0]), static_cast<int>(rgb[1]), static_cast<int>(rgb[2])};
}

std::size_t sizeCount(ShapeKind k) {
  return (k == ShapeKind::Cube || k == ShapeKind::Sphere) ? 1 : 3;
}

// A cylinder's [base radius, top radius, height]: a radius of 0 makes a
// cone (its point at the top or at the base), but not both; empty on error.
std::vector<double> cylinderSizes(Fields& f, const json& size) {
  std::vector<double> s = f.numbers(size, f.at("size"), 3, 3, ranges::Range{0.0, kLength.hi, false});
  if (s.size() != 3) return {};
  bool fine = true;
  for (std::size_t i = 0; i < 3; ++i) {
    const bool radius = i < 2;
    if (radius && s[i] == 0.0) continue;
    if (!ranges::inRange(s[i], kLength)) {
      f.fail(f.at("size") + "/" + std::to_string(i),
             std::string("expected ") + (radius ? "0 (a cone's point) or " : "") + rangeText(kLength) + ", got " +
                 ranges::number(s[i]));
      fine = false;
    }
  }
  if (fine && s[0] == 0.0 && s[1] == 0.0) {
    f.fail(f.at("size"), "expected a radius above 0 at one end at least (a cone has one), got [0, 0, ...]");
    fine = false;
  }
  return fine ? s : std::vector<double>{};
}

}  // namespace

Material readMaterial(Fields& parent, const std::string& key, Material m,
                      std::vector<Problem>& problems) {
  const json* v = parent.get(key, false);
  if (!v) return m;
  Fields f(*v, parent.at(key), problems);
  m.friction = f.number("friction", kFriction, m.friction);
  m.rollingFriction = f.number("rolling_friction", kFriction, m.rollingFriction);
  // A ball on a table stops spinning too: spinning friction follows rolling
  // friction unless given.
  m.spinningFriction = f.number("spinning_friction", kFriction,
                                f.has("rolling_friction") ? m.rollingFriction : m.spinningFriction);
  m.restitution = f.number("restitution", kUnitInterval, m.restitution);
  f.finish();
  return m;
}


TableSpec readTable(const json& j, std::vector<Problem>& problems) {
  TableSpec t;
  Fields f(j, "/table", problems);
  if (const json* size = f.get("size", false)) {
    const auto wd = f.numbers(*size, f.at("size"), 2, 2, kLength);
    if (wd.size() == 2) {
      t.width = wd[0];
      t.depth = wd[1];
    }
  }
  t.height = f.number("height", kLength, t.height);
  t.thickness = f.number("thickness", kLength, t.thickness);
  t.legRadius = f.number("leg_radius", kLength, t.legRadius);
  if (const json* centre = f.get("centre", false)) {
    const auto xz = f.numbers(*centre, f.at("centre"), 2, 2, kCoordinate);
    if (xz.size() == 2) {
      t.centreX = xz[0];
      t.centreZ = xz[1];
    }
  }
  t.material = readMaterial(f, "material", t.material, problems);
  t.colour = readColour(f, "colour", t.colour);
  f.finish();
  if (f.valid() && t.thickness >= t.height) {
    f.fail("/table/thickness", "expected less than the table height (" + std::to_string(t.height) + " m)");
  }
  if (f.valid() && 4.0 * t.legRadius >= std::min(t.width, t.depth)) {
    f.fail("/table/leg_radius", "expected less than a quarter of the table's width and depth");
  }
  return t;
}


Settings readSettings(const json& j, std::vector<Problem>& problems) {
  Settings s;
  Fields f(j, "/settings", problems);
  s.timestep = f.number("timestep", kTimestep, s.timestep);
  integer(f, "iterations", kIterations, s.iterations);
  integer(f, "max_substeps", kMaxSubsteps, s.maxSubsteps);
  choice(f, "solver", kAllContactSolvers, s.solver);
  s.duration = f.number("duration", kSpan, s.duration);
  s.gravity = f.number("gravity", kGravity, s.gravity);
  s.endAtRest = f.boolean("end_at_rest", s.endAtRest);
  s.bullet.sleeping = f.boolean("sleeping", s.bullet.sleeping);
  choice(f, "integrator", kAllIntegrators, s.integrator);
  s.bullet.warmStart = f.number("warm_start", kUnitInterval, s.bullet.warmStart);
  s.bullet.solverTolerance = f.number("solver_tolerance", kSpeedTolerance, s.bullet.solverTolerance);
  choice(f, "gyroscopic", kAllGyroscopics, s.bullet.gyroscopic);
  choice(f, "broadphase", kAllBroadphases, s.bullet.broadphase);
  s.bullet.legsWhenReachable = f.boolean("legs_when_reachable", s.bullet.legsWhenReachable);
  s.bullet.floorPairsNearFloor = f.boolean("floor_pairs_near_floor", s.bullet.floorPairsNearFloor);
  f.finish();
  return s;
}

// How many numbers each shape's "size" holds, and what they mean.


// `sized`: whether its shape and size were read (else its geometry is the
// default, and nothing is checked against it).
EntitySpec readEntity(const json& j, const std::string& path, const NameIndex& earlier,
                      std::vector<Problem>& problems, bool& sized) {
  EntitySpec e;
  e.path = path;
  Fields f(j, path, problems);
  e.name = f.string("name", "", true, ScenarioLoader::kMaxNameBytes);
  if (!e.name.empty() && earlier.count(e.name)) {
    f.fail(f.at("name"), "expected a unique name, but " + quotedName(e.name) + " is already used");
  }
  if (e.name == "table" || e.name == "ground" || e.name == "none") {
    f.fail(f.at("name"), quotedName(e.name) + " is reserved; expected another name");
  }

  std::optional<ShapeKind> kind;
  const std::string shape = f.string("shape", "", true);
  if (!shape.empty()) {
    kind = shapeKindFromString(shape);
    if (!kind) f.fail(f.at("shape"), "expected one of cube, sphere, box, cylinder, got " + quotedValue(shape));
  }

  sized = false;
  if (const json* size = f.get("size", true); size && kind) {
    std::vector<double> sizes;
    if (sizeCount(*kind) == 1) {
      const double s = f.checkNumber(*size, f.at("size"), kLength, 0.0);
      if (s > 0.0) sizes = {s};
    } else if (*kind == ShapeKind::Cylinder) {
      sizes = cylinderSizes(f, *size);
    } else {
      sizes = f.numbers(*size, f.at("size"), 3, 3, kLength);
    }
    if (const auto geometry = ShapeGeometry::fromSizes(*kind, sizes)) {
      e.geometry = *geometry;
      sized = true;
    }
  }

  const std::string on = f.has("on") ? f.string("on", "") : "";
  e.on = Support::named(on);
  if (const json* pos = f.get("position", true)) {
    const auto p = f.numbers(*pos, f.at("position"), 2, 3, kCoordinate);
    if (p.size() == 3) {
      e.position = {p[0], p[1], p[2]};
      if (!on.empty()) f.fail(f.at("on"), "expected no 'on' when the position gives a height [x, y, z]");
    } else if (p.size() == 2) {
      e.position = {p[0], 0.0, p[1]};
      if (on.empty()) e.on = Support::table();
    }
  }
  if ((on == "none" || e.on.isEntity()) && !earlier.count(on)) {
    f.fail(f.at("on"), "expected \"table\", \"ground\" or an entity listed before this one, got " +
                           shown(*f.get("on", false)));
  }

  e.yawDegrees = f.number("yaw", kAngle, 0.0);
  if (const std::optional<Quat> q = readOrientation(f)) {
    if (f.has("yaw")) f.fail(f.at("yaw"), "expected 'yaw' or 'orientation', not both");
    if (!onlyYaw(*q, e.yawDegrees)) e.orientation = q;
  }
  e.colour = readColour(f, "colour", e.colour);
  e.mass = f.number("mass", kMass, e.mass, true);
  e.material = readMaterial(f, "material", e.material, problems);
  // The motion it starts with (full physics only; the report's rules start
  // every entity at rest).
  e.velocity = f.vec3("velocity", kSpeed).value_or(e.velocity);
  e.spin = f.vec3("spin", kSpin).value_or(e.spin);
  f.finish();
  return e;
}

Action readAction(const json& j, const std::string& path, const NameIndex& entities,
                  std::vector<Problem>& problems) {
  Action a;
  a.path = path;
  Fields f(j, path, problems);
  if (f.has("t")) a.at = f.number("t", kTime, 0.0);

  auto checkEntity = [&](Fields& g, const std::string& name) {
    if (name.empty() || entities.count(name)) return;
    g.fail(g.at("entity"), "expected the name of an entity, got " + quotedValue(name));
  };

  const int kinds = int(f.has("push")) + int(f.has("rotate")) + int(f.has("wait"));
  if (f.valid() && kinds != 1) {
    f.fail(path, "expected exactly one of 'push', 'rotate', 'wait'");
  }
  if (const json* push = f.get("push", false)) {
    a.type = Action::Type::Push;
    Fields p(*push, f.at("push"), problems);
    a.arrow.entity = p.string("entity", "", true);
    checkEntity(p, a.arrow.entity);
    const bool byFace = p.has("direction"), byAngle = p.has("angle");
    if (p.valid() && byFace == byAngle) p.fail(f.at("push"), "expected exactly one of 'direction', 'angle'");
    if (byFace) {
      const std::string d = p.string("direction", "");
      if (auto dir = directionFromString(d)) {
        a.arrow.face = *dir;
      } else if (!d.empty()) {
        p.fail(p.at("direction"), "expected one of Left, Right, Front, Back, got " + quotedValue(d));
      }
    }
    if (byAngle) a.arrow.angleDegrees = p.number("angle", kAngle, 0.0);
    const bool byStep = p.has("step"), byImpulse = p.has("impulse");
    if (p.valid() && byStep == byImpulse) p.fail(f.at("push"), "expected exactly one of 'step', 'impulse'");
    if (byStep) a.magnitude = {PushMagnitude::Kind::Step, p.number("step", kStep, 0.0)};
    if (byImpulse) {
      a.magnitude = {PushMagnitude::Kind::Impulse, p.number("impulse", kImpulse, 0.0)};
    }
    if (p.has("at")) {
      a.arrow.at = p.vec3("at", kLengthOffset);
      if (p.valid() && byStep) {
        p.fail(p.at("at"), "expected 'impulse' with 'at': a step is the travel of a push through the centre");
      }
    }
    p.finish();
  }
  if (const json* rotate = f.get("rotate", false)) {
    a.type = Action::Type::Rotate;
    Fields r(*rotate, f.at("rotate"), problems);
    a.entity = r.string("entity", "", true);
    checkEntity(r, a.entity);
    a.degrees = r.number("angle", kAngle, 0.0, true);
    r.finish();
  }
  if (const json* wait = f.get("wait", false)) {
    if (wait->is_string() && wait->get<std::string>() == "rest") {
      a.type = Action::Type::WaitRest;
      a.seconds = f.number("timeout", kSpan, 0.0);
    } else if (wait->is_number()) {
      a.type = Action::Type::WaitTime;
      a.seconds = f.checkNumber(*wait, f.at("wait"), kSpan, 0.0);
    } else {
      f.fail(f.at("wait"), "expected \"rest\" or a positive number of seconds, got " + shown(*wait));
    }
  }
  f.finish();
  return a;
}

// An entity set on the table starts with its centre over the top: one
// placed beyond an edge would start in mid-air beside the table.
void checkOverTable(const EntitySpec& e, const TableSpec& t, std::vector<Problem>& problems) {
  if (e.on != Support::table()) return;
  const double halfW = 0.5 * t.width, halfD = 0.5 * t.depth;
  if (std::abs(e.position.x - t.centreX) <= halfW && std::abs(e.position.z - t.centreZ) <= halfD) return;
  problems.push_back({e.path + "/position", "expected a centre over the table top (x from " +
                                                number(t.centreX - halfW) + " to " + number(t.centreX + halfW) +
                                                ", z from " + number(t.centreZ - halfD) + " to " +
                                                number(t.centreZ + halfD) + " m), got [" + number(e.position.x) +
                                                ", " + number(e.position.z) + "]"});
}

// An entity set on another stands over it: its centre within the other's
// top. One placed beside its base would be seated at the base's height and
// float there.
void checkOverBase(const EntitySpec& e, const EntitySpec& base, std::vector<Problem>& problems) {
  if (base.orientation) {
    problems.push_back({e.path + "/on", "expected an upright entity to rest on: " + quotedName(base.name) +
                                            " is tilted, and its top is no level face"});
    return;
  }
  const auto [hx, hz] = base.geometry.topFootprint(base.yawDegrees);
  const double dx = e.position.x - base.position.x, dz = e.position.z - base.position.z;
  const bool over = base.geometry.round() ? std::hypot(dx, dz) <= hx : std::abs(dx) <= hx && std::abs(dz) <= hz;
  if (over) return;
  problems.push_back({e.path + "/position", "expected a centre over the top of " + quotedName(base.name) +
                                                " (within " + number(hx) + " m of [" + number(base.position.x) +
                                                ", " + number(base.position.z) + "]), got [" + number(e.position.x) +
                                                ", " + number(e.position.z) + "]"});
}

}  // namespace tabletop::parts
