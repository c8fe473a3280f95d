#include "measure/LawSweep.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>

#include "core/ShapeGeometry.h"
#include "core/Simulation.h"
#include "io/ProcessPool.h"
#include "physics/StepPush.h"
#include "scenario/ScenarioLoader.h"
#include "scenes/ConeRoll.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

struct ShapeSize {
  const char* shape;
  const char* size;
  double radius;  // a sphere's, or a cylinder's lying on its side, m
  double below;   // m, its centre of mass above its lowest point, standing
  PushCase::Lying lying = PushCase::Lying::Upright;
};

const ShapeSize kSolids[] = {
    {"cube", "0.1", 0, 0.05},
    {"box", "[0.2, 0.05, 0.12]", 0, 0.025},
    {"cylinder", "[0.05, 0.05, 0.1]", 0, 0.05},
    {"cylinder", "[0.08, 0.08, 0.03]", 0, 0.015},
    {"cylinder", "[0.05, 0.03, 0.1]", 0, ShapeGeometry::cylinder(0.05, 0.03, 0.1).below()}};
const ShapeSize kSpheres[] = {{"sphere", "0.05", 0.05, 0.05}, {"sphere", "0.1", 0.1, 0.1}};
// A cylinder lying on its side rolls when pushed across its axis and
// slides when pushed along it.
const ShapeSize kRolling = {"cylinder", "[0.05, 0.05, 0.1]", 0.05, 0.05, PushCase::Lying::Across};
const ShapeSize kSlidingAlong = {"cylinder", "[0.05, 0.05, 0.1]", 0.05, 0.05, PushCase::Lying::Along};
// Cones and a truncated cone rolling on their sides (scenes/ConeRoll.h).
struct Roller {
  ShapeSize shape;
  double base, top, height;  // m
};
const Roller kRollers[] = {{{"cylinder", "[0.05, 0, 0.1]", 0, 0}, 0.05, 0, 0.1},
                           {{"cylinder", "[0.03, 0, 0.12]", 0, 0}, 0.03, 0, 0.12},
                           {{"cylinder", "[0.05, 0.03, 0.1]", 0, 0}, 0.05, 0.03, 0.1}};
const double kPrecessions[] = {-2.0, 3.0};  // rad/s
// The box of free rotation's law, spun at kFreeSpin for kFreeDuration.
const ShapeSize kTumbler = {"box", "[0.1, 0.2, 0.3]", 0, 0.1};
constexpr double kFreeSpin = 5.0;       // rad/s
constexpr double kFreeDuration = 10.0;  // s
const double kRestitutions[] = {0.0, 0.5, 0.9};
const double kAngles[] = {0.0, 45.0, 77.0, 200.0};

constexpr double kSlideImpulse = 2.4;  // N s: v0 = 1.6 m/s
constexpr double kRollImpulse = 0.6;   // N s: v0 = 0.4 m/s
constexpr double kRollingFriction = 0.002;  // m
constexpr double kStep = 0.2;          // m
constexpr double kStrikeImpulse = 0.225;  // N s: 0.15 m/s
const double kSpins[] = {5.0, -12.0};  // rad/s about the vertical

// How far a body turned, degrees: an upright one's yaw, a lying one's
// axis away from its start (level, across or along the push).
double turnOf(const EntityState& a, const PushCase& c) {
  if (c.lying == PushCase::Lying::Upright) return std::abs(a.yawDegrees);
  const auto [w, x, y, z] = a.orientation;
  const double angle = c.angle * std::acos(-1.0) / 180.0;
  const bool across = c.lying == PushCase::Lying::Across;
  const double ux = across ? std::sin(angle) : std::cos(angle), uz = across ? std::cos(angle) : -std::sin(angle);
  const double along = std::abs(2 * (x * y - w * z) * ux + 2 * (y * z + w * x) * uz);
  return std::acos(std::min(1.0, along)) * 180.0 / std::acos(-1.0);
}

// One law for one shape on one support at one rate: the worst over angles.
LawPoint measure(const std::string& law, const ShapeSize& shape, const char* support, double rate) {
  const std::string lying = shape.lying == PushCase::Lying::Across  ? " lying across"
                            : shape.lying == PushCase::Lying::Along ? " lying along"
                                                                    : "";
  LawPoint point{law, std::string(shape.shape) + " " + shape.size + lying, support, rate, 0.0, 0.0};
  const bool sphere = shape.radius > 0 && shape.lying == PushCase::Lying::Upright;
  const bool rolls = sphere || shape.lying == PushCase::Lying::Across;
  for (const double angle : kAngles) {
    PushCase c{shape.shape, shape.size, support, angle, rate};
    c.lying = shape.lying;
    if (rolls) c.rollingFriction = kRollingFriction;
    if (law == "step") {
      c.step = kStep;
    } else {
      c.impulse = rolls ? kRollImpulse : kSlideImpulse;
    }
    const Scenario s = pushScene(c);
    const double g = s.settings.gravity, v0 = c.impulse / kPushedMass;
    const double expected = law == "step"    ? kStep
                            : law == "roll" ? rollingDistance(v0, c.friction, c.rollingFriction, shape.radius, g,
                                                              sphere ? 0.4 : 0.5)
                                            : slidingDistance(v0, c.friction, g);
    auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
    const RunResult r = runScript(s, s.settings, *sim);
    const EntityState& a = r.entities.back();
    const auto [x0, z0] = pushStart(c);
    const double error = r.complete ? std::abs(std::hypot(a.position.x - x0, a.position.z - z0) - expected) : INFINITY;
    point.worstError = std::max(point.worstError, error);
    if (!sphere) point.worstTurn = std::max(point.worstTurn, turnOf(a, c));
  }
  return point;
}

// A spin on the base against its closed form (spinLaw): the worst
// distance its contact points end from where the closed form puts them
// (rho times the angle's error), and the worst drift, m.
LawPoint measureSpin(const ShapeSize& shape, const char* support, double rate) {
  LawPoint point{"spin", std::string(shape.shape) + " " + shape.size, support, rate, 0.0, 0.0};
  for (const double w0 : kSpins) {
    PushCase c{shape.shape, shape.size, support, 0.0, rate};
    c.spin = w0;
    const Scenario s = pushScene(c);
    const std::optional<SpinLaw> law = spinLaw(c);
    if (!law) return point;
    auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
    const RunResult r = runScript(s, s.settings, *sim);
    const EntityState& a = r.entities.back();
    const auto [x0, z0] = pushStart(c);
    const double turned = a.yawDegrees * std::acos(-1.0) / 180.0;
    const double error = r.complete ? std::max(law->rho * std::abs(turned - law->angle),
                                               std::hypot(a.position.x - x0, a.position.z - z0))
                                    : INFINITY;
    point.worstError = std::max(point.worstError, error);
  }
  return point;
}

// A cone rolling on its side against its circle (rollCentre()): the worst
// distance of its centre of mass from the circle over the run.
LawPoint measureCircle(const ShapeSize& shape, const char* support, double rate) {
  LawPoint point{"circle", std::string(shape.shape) + " " + shape.size, support, rate, 0.0, 0.0};
  for (const Roller& roller : kRollers) {
    if (&roller.shape != &shape) continue;
    for (const double precession : kPrecessions) {
      RollCase c;
      c.support = support;
      c.baseRadius = roller.base, c.topRadius = roller.top, c.height = roller.height;
      c.precession = precession;
      c.rate = rate;
      const Scenario s = rollScene(c);
      const Vec3 apex = rollApex(c), start = rollCentre(c, 0);
      const double radius = std::hypot(start.x - apex.x, start.z - apex.z);
      auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
      while (sim->time() + 0.5 * s.settings.timestep < kRollDuration) {
        sim->step();
        const Vec3 x = sim->snapshot().back().position;
        point.worstError =
            std::max(point.worstError, std::hypot(std::hypot(x.x - apex.x, x.z - apex.z) - radius, x.y - start.y));
      }
    }
  }
  return point;
}

// A box struck level with its centre but off it, on a frictionless
// support, against the closed form: it slides at J / m and turns at
// (r x J) / I about the vertical. The worst distance of its centre from
// J t / m past its start, or of its corners from their closed-form place
// (its half diagonal times the turn's error), after the run.
LawPoint measureStrike(const ShapeSize& shape, const char* support, double rate) {
  LawPoint point{"strike", std::string(shape.shape) + " " + shape.size, support, rate, 0.0, 0.0};
  for (const double angle : kAngles) {
    PushCase c{shape.shape, shape.size, support, angle, rate};
    c.friction = 0;
    c.impulse = kStrikeImpulse;
    const Scenario s = pushScene(c);
    const ShapeGeometry& g = s.entities.back().geometry;
    const Vec3 half = g.halfExtents();
    c.at = Vec3{0.8 * half.x, 0, 0.5 * half.z};
    const Scenario struck = pushScene(c);
    auto sim = buildSimulation(struck, struck.settings, SimulationMode::Bullet);
    const RunResult r = runScript(struck, struck.settings, *sim);
    const EntityState& a = r.entities.back();
    const double rad = angle * std::acos(-1.0) / 180.0;
    const double jx = c.impulse * std::cos(rad), jz = -c.impulse * std::sin(rad);
    const double m = kPushedMass, t = r.simTime;
    const double turnRate = (c.at->z * jx - c.at->x * jz) / g.inertia(m).y;
    const auto [x0, z0] = pushStart(c);
    const double moved = std::hypot(a.position.x - (x0 + jx / m * t), a.position.z - (z0 + jz / m * t));
    const double turned = std::remainder(a.yawDegrees * std::acos(-1.0) / 180.0 - turnRate * t, 2 * std::acos(-1.0));
    const double error = r.complete ? std::max(moved, std::hypot(half.x, half.z) * std::abs(turned)) : INFINITY;
    point.worstError = std::max(point.worstError, error);
  }
  return point;
}

// A box spun about each of its principal axes in free flight (no
// gravity) for 10 s against the closed form, a steady turn at its spin:
// the worst distance of a corner from its closed-form place.
LawPoint measureFree(double rate) {
  LawPoint point{"free", std::string(kTumbler.shape) + " " + kTumbler.size, "none", rate, 0.0, 0.0};
  for (int axis = 0; axis < 3; ++axis) {
    std::ostringstream text;
    text.precision(17);
    const double w[3] = {axis == 0 ? kFreeSpin : 0.0, axis == 1 ? kFreeSpin : 0.0, axis == 2 ? kFreeSpin : 0.0};
    text << R"({"version": 1, "name": "free", "settings": {"gravity": 0, "duration": )" << kFreeDuration
         << R"(, "end_at_rest": false, "timestep": )" << 1.0 / rate << R"(}, "entities": [{"name": "A", "shape": ")"
         << kTumbler.shape << R"(", "size": )" << kTumbler.size << R"(, "position": [0, 2, 0], "mass": 1, "spin": [)"
         << w[0] << ", " << w[1] << ", " << w[2] << "]}]}";
    Scenario s = ScenarioLoader::loadText(text.str(), "free.json");
    s.settings.timestep = 1.0 / rate;
    auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
    const RunResult r = runScript(s, s.settings, *sim);
    const EntityState& a = r.entities.back();
    // The closed form: turned by w t about the axis, centre where it was.
    const Quat q = Quat::about({w[0] / kFreeSpin, w[1] / kFreeSpin, w[2] / kFreeSpin}, kFreeSpin * r.simTime);
    const Vec3 half = s.entities.back().geometry.halfExtents();
    const Quat turned{a.orientation[0], a.orientation[1], a.orientation[2], a.orientation[3]};
    double worst = std::hypot(std::hypot(a.position.x, a.position.y - 2), a.position.z);
    for (const double sx : {-1.0, 1.0}) {
      for (const double sy : {-1.0, 1.0}) {
        for (const double sz : {-1.0, 1.0}) {
          const Vec3 corner{sx * half.x, sy * half.y, sz * half.z};
          worst = std::max(worst, (turned.rotate(corner) - q.rotate(corner)).length());
        }
      }
    }
    point.worstError = std::max(point.worstError, r.complete ? worst : INFINITY);
  }
  return point;
}

// A drop from kDropHeight against dropHeight(), followed until dropEnd():
// the worst error of the centre's height.
LawPoint measureBounce(const ShapeSize& shape, const char* support, double rate) {
  LawPoint point{"bounce", std::string(shape.shape) + " " + shape.size, support, rate, 0.0, 0.0};
  for (const double e : kRestitutions) {
    const DropCase c{shape.shape, shape.size, shape.below, support, e, rate};
    const Scenario s = dropScene(c);
    const double g = s.settings.gravity, end = dropEnd(c, g);
    auto sim = buildSimulation(s, s.settings, SimulationMode::Bullet);
    while (sim->time() + s.settings.timestep <= end) {
      sim->step();
      const double exact = dropHeight(c, g, sim->time());
      const EntityState body = sim->snapshot().back();
      point.worstError = std::max(point.worstError, std::abs(body.position.y - exact));
      if (shape.radius == 0) point.worstTurn = std::max(point.worstTurn, std::abs(body.yawDegrees));
    }
  }
  return point;
}

}  // namespace

std::vector<LawPoint> measureLaws(const std::vector<double>& rates, const MeasureHooks& hooks, int jobs) {
  std::vector<std::tuple<std::string, const ShapeSize*>> laws;
  for (const ShapeSize& s : kSolids) laws.emplace_back("slide", &s);
  laws.emplace_back("slide", &kSlidingAlong);
  for (const ShapeSize& s : kSpheres) laws.emplace_back("roll", &s);
  laws.emplace_back("roll", &kRolling);
  for (const ShapeSize& s : kSolids) laws.emplace_back("step", &s);
  for (const ShapeSize& s : kSpheres) laws.emplace_back("step", &s);
  for (const ShapeSize& s : kSolids) laws.emplace_back("spin", &s);
  for (const Roller& r : kRollers) laws.emplace_back("circle", &r.shape);
  laws.emplace_back("strike", &kSolids[0]);
  laws.emplace_back("strike", &kSolids[1]);
  laws.emplace_back("bounce", &kSpheres[0]);
  for (const ShapeSize& s : kSolids) laws.emplace_back("bounce", &s);
  // One run per law, shape, support and rate, in that order.
  struct Run {
    const std::string* law;
    const ShapeSize* shape;
    const char* support;
    double rate;
  };
  std::vector<Run> runs;
  for (const auto& [law, shape] : laws) {
    for (const char* support : kLawSupports) {
      for (const double rate : rates) runs.push_back({&law, shape, support, rate});
    }
  }
  // Free rotation has no support: one row, in free flight.
  const std::string free = "free";
  for (const double rate : rates) runs.push_back({&free, &kTumbler, "none", rate});
  hooks.start(static_cast<long>(runs.size()));
  const auto measureRun = [&runs](std::size_t i) {
    const Run& r = runs[i];
    return *r.law == "bounce" ? measureBounce(*r.shape, r.support, r.rate)
           : *r.law == "spin" ? measureSpin(*r.shape, r.support, r.rate)
           : *r.law == "circle" ? measureCircle(*r.shape, r.support, r.rate)
           : *r.law == "strike" ? measureStrike(*r.shape, r.support, r.rate)
           : *r.law == "free" ? measureFree(r.rate)
                              : measure(*r.law, *r.shape, r.support, r.rate);
  };
  std::vector<LawPoint> points;
  const auto take = [&](const Run& r, LawPoint p) {
    hooks.advance(*r.law + " " + r.shape->shape);
    points.push_back(std::move(p));
  };
  if (std::min<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), runs.size()) <= 1) {
    for (std::size_t i = 0; i < runs.size() && !hooks.stop(); ++i) take(runs[i], measureRun(i));
    return points;
  }
  // A run that did not complete has an infinite error, which JSON cannot
  // hold: it travels as null.
  const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  const auto back = [](const nlohmann::json& v) { return v.is_null() ? INFINITY : v.get<double>(); };
  runProcessPool(0, runs.size(), jobs, [&](std::size_t i) {
    const LawPoint p = measureRun(i);
    return PoolRow{i, p.shape, number(p.worstError), number(p.worstTurn)};
  }, [&](const PoolRow& row) {
    const Run& r = runs[row[0].get<std::size_t>()];
    take(r, {*r.law, row[1].get<std::string>(), r.support, r.rate, back(row[2]), back(row[3])});
  }, hooks.stop);
  return points;
}

ResultTable lawTable(const std::vector<LawPoint>& points) {
  ResultTable t;
  t.title =
      "laws: the worst error against the closed form, over pushes at 0, 45, 77 and 200 degrees, over drops at "
      "e = 0, 0.5 and 0.9, over spins of 5 and -12 rad/s, or over precessions of -2 and 3 rad/s (a strike: over "
      "its angles)";
  std::vector<double> rates;
  for (const LawPoint& p : points) {
    if (std::find(rates.begin(), rates.end(), p.rate) == rates.end()) rates.push_back(p.rate);
  }
  t.columns = {{"law", "law"}, {"shape", "shape"}, {"support", "support"}};
  for (const double rate : rates) {
    const std::string hz = std::to_string(static_cast<int>(std::lround(rate)));
    t.columns.push_back({"error_m_" + hz + "_hz", "error [mm] " + hz + " Hz"});
  }
  t.columns.push_back({"turn_deg", "turn [deg]"});
  // Rows in the order measured; one per law, shape and support.
  std::vector<std::tuple<std::string, std::string, std::string>> keys;
  std::map<std::tuple<std::string, std::string, std::string>, std::vector<const LawPoint*>> byKey;
  for (const LawPoint& p : points) {
    const auto key = std::make_tuple(p.law, p.shape, p.support);
    if (byKey.find(key) == byKey.end()) keys.push_back(key);
    byKey[key].push_back(&p);
  }
  for (const auto& key : keys) {
    const auto& [law, shape, support] = key;
    std::vector<ResultTable::Cell> row = {cell(law), cell(shape), cell(support)};
    double turn = 0;
    for (const double rate : rates) {
      const auto& measured = byKey[key];
      const auto found = std::find_if(measured.begin(), measured.end(), [&](const LawPoint* p) { return p->rate == rate; });
      if (found == measured.end()) {
        row.push_back(cell(nullptr, ""));
        continue;
      }
      row.push_back(cell(nlohmann::json((*found)->worstError), ResultTable::Cell(cell((*found)->worstError * 1000.0, 4)).shown));
      turn = std::max(turn, (*found)->worstTurn);
    }
    const bool noTurn =
        shape.rfind("sphere", 0) == 0 || law == "spin" || law == "circle" || law == "strike" || law == "free";
    row.push_back(noTurn ? cell(nullptr, "-") : cell(turn, 3));
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace tabletop
