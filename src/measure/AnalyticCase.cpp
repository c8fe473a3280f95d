#include "measure/AnalyticCase.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "physics/contact/ContactMaterial.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

const char* const kNames[] = {"cube_slides_to_rest",    "sphere_slip_to_roll", "free_flight",
                              "projectile_off_the_edge", "head_on_spheres",     "cube_tips_off_the_edge",
                              "stack_rides_along",       "stack_rider_slips",   "straight_line_transfer"};

// The turning rate, rad/s, above which a cube crossing the edge counts as
// tipping: well above the solver's noise on a gliding cube (at most
// 1.2e-3 rad/s, at 60 Hz), and reached within a few steps of the centre
// passing the edge at any rate from 30 Hz to 4000 Hz.
constexpr double kTippingRate = 0.02;

[[noreturn]] void unfit(const Scenario& s, const std::string& why) {
  throw std::invalid_argument(s.file + ": not the analytic case '" + s.name + "': " + why);
}

const EntitySpec& entity(const Scenario& s, std::size_t i) {
  if (i >= s.entities.size()) unfit(s, "expected " + std::to_string(i + 1) + " entities");
  return s.entities[i];
}

// The scenario's first push: on the first entity, at t = 0, along +x.
const Action& firstPush(const Scenario& s) {
  for (const Action& a : s.script) {
    if (a.type != Action::Type::Push) continue;
    if (a.arrow.worldAngleDegrees(s.entities.front().yawDegrees) != 0.0 ||
        a.arrow.entity != s.entities.front().name || a.at.value_or(0.0) != 0.0) {
      unfit(s, "expected its first action to push the first entity at t = 0 along +x");
    }
    return a;
  }
  unfit(s, "expected a push");
}

// The speed the scenario's first push gives its entity, m/s, along +x.
double launchSpeed(const Scenario& s) {
  const Action& a = firstPush(s);
  if (a.magnitude.kind != PushMagnitude::Kind::Impulse) unfit(s, "expected the push to be an impulse");
  return a.magnitude.value / s.entities.front().mass;
}

// The length of the first push's step, m.
double pushStep(const Scenario& s) {
  const Action& a = firstPush(s);
  if (a.magnitude.kind != PushMagnitude::Kind::Step) unfit(s, "expected the push to be a step");
  return a.magnitude.value;
}

// Where a pushed cube A carrying cube B on its top ends, and where B does
// (m, from their start), sliding from v0 on a table of friction mu1 with
// friction mu2 between them. B first slips back on A until both move at
// v1 (t1 = v0 / (aB - aA)); then either they slow together at mu1 g
// (mu1 <= mu2: B rides along) or A slows faster than friction lets B, A
// stops first and B slides on at mu2 g.
struct StackTravel {
  double a = 0.0, b = 0.0;
};
StackTravel stackTravel(double v0, double mA, double mB, double mu1, double mu2, double g) {
  const double aB = mu2 * g, aA = -(mu2 * mB + mu1 * (mA + mB)) * g / mA;
  const double t1 = v0 / (aB - aA), v1 = aB * t1;
  StackTravel d{v0 * t1 + 0.5 * aA * t1 * t1, 0.5 * aB * t1 * t1};
  if (mu1 <= mu2) {
    d.a += v1 * v1 / (2.0 * mu1 * g);
    d.b += v1 * v1 / (2.0 * mu1 * g);
  } else {
    const double aA2 = (mu1 * (mA + mB) - mu2 * mB) * g / mA;
    d.a += v1 * v1 / (2.0 * aA2);
    d.b += v1 * v1 / (2.0 * mu2 * g);
  }
  return d;
}

double tableFriction(const Scenario& s, const EntitySpec& e) { return combine(e.material, s.table.material).friction; }

std::size_t indexOf(const RunResult& r, const std::string& name) {
  for (std::size_t i = 0; i < r.entities.size(); ++i) {
    if (r.entities[i].name == name) return i;
  }
  throw std::logic_error("no entity " + name);
}

}  // namespace

double AnalyticMeasure::error() const { return std::abs(measured - truth); }

std::optional<AnalyticCase> AnalyticCase::forScenario(const Scenario& scenario) {
  for (const char* n : kNames) {
    if (scenario.name == n) return AnalyticCase(n);
  }
  return std::nullopt;
}

std::vector<std::string> AnalyticCase::names() { return {std::begin(kNames), std::end(kNames)}; }

std::string AnalyticCase::motion(const std::string& name) {
  static const std::map<std::string, std::string> kMotions = {
      {"free_flight", "flight"},
      {"projectile_off_the_edge", "leaving the table"},
      {"cube_tips_off_the_edge", "leaving the table"},
      {"cube_slides_to_rest", "sliding"},
      {"sphere_slip_to_roll", "rolling"},
      {"head_on_spheres", "collision"},
      {"straight_line_transfer", "collision"},
      {"stack_rides_along", "stacking"},
      {"stack_rider_slips", "stacking"}};
  const auto it = kMotions.find(name);
  return it == kMotions.end() ? std::string() : it->second;
}

AnalyticResult AnalyticCase::run(const Scenario& s, const Settings& settings, SimulationMode mode) const {
  const double g = settings.gravity;
  const EntitySpec& a = entity(s, 0);
  const double v0 = name_ == "straight_line_transfer" ? 0.0 : launchSpeed(s);
  auto simulation = buildSimulation(s, settings, mode);

  // Where the first entity's centre first comes down to `level`, for the
  // projectile. Steps see the landing only at their ends: the first step
  // whose vertical velocity rises, once the entity has fallen below the
  // table top, holds the impact, and the point within that step is where
  // the entity's own state at the step before meets `level` in free
  // flight, y + vy t - g t^2 / 2 = level. That is the time of impact
  // continuous collision detection would report; the state it starts
  // from is the simulator's, so any error of the flight or of leaving the
  // edge stays in the measure.
  std::optional<double> landingX;
  const double level = a.geometry.kind() == ShapeKind::Sphere ? a.geometry.sizes()[0] : 0.5 * a.geometry.sizes()[0];
  std::optional<BodyMotion> previous;
  const auto watch = [&](const Simulation& sim) {
    const BodyMotion now = sim.motions().front();
    if (!landingX && previous && previous->position.y < s.table.height &&
        now.linearVelocity.y > previous->linearVelocity.y) {
      const double y = previous->position.y - level, vy = previous->linearVelocity.y;
      const double t = (vy + std::sqrt(std::max(0.0, vy * vy + 2.0 * g * y))) / g;
      landingX = previous->position.x + previous->linearVelocity.x * t;
    }
    previous = now;
  };

  // Where the cube's centre stood when it started to tip over the edge. Its
  // turning rate is watched until it passes kTippingRate; then the start is
  // read back from how the rate grows: with the centre a distance
  // s = v (t - tc) past the edge and the frictionless edge's push m g up,
  // I w' = m g s with I = m a^2 / 6 gives w = 3 g v (t - tc)^2 / a^2, so the
  // centre passed the edge v a sqrt(w / (3 g v)) before where it is now.
  std::optional<double> tippingX;
  const auto watchTipping = [&](const Simulation& sim) {
    const BodyMotion now = sim.motions().front();
    const double w = now.angularVelocity.length(), v = now.linearVelocity.x;
    if (tippingX || w < kTippingRate || v <= 0) return;
    tippingX = now.position.x - v * a.geometry.sizes()[0] * std::sqrt(w / (3.0 * g * v));
  };

  AnalyticResult result;
  StepObserver observer;
  if (name_ == "projectile_off_the_edge") observer = watch;
  if (name_ == "cube_tips_off_the_edge") observer = watchTipping;
  result.run = runScript(s, settings, *simulation, observer);
  const RunResult& r = result.run;
  const double T = r.simTime;
  const EntityState& endA = r.entities.at(0);
  auto& m = result.measures;

  if (name_ == "cube_slides_to_rest") {
    const double mu = tableFriction(s, a);
    m.push_back({a.name + " distance slid", "m", v0 * v0 / (2.0 * mu * g), endA.position.x - a.position.x});
    m.push_back({a.name + " sideways drift", "m", 0.0, endA.position.z - a.position.z});
  } else if (name_ == "sphere_slip_to_roll") {
    const double mu = tableFriction(s, a);
    const double t1 = 2.0 * v0 / (7.0 * mu * g), v1 = 5.0 / 7.0 * v0;
    if (T < t1) unfit(s, "expected a duration past the end of slipping");
    m.push_back({a.name + " distance at T", "m", v0 * t1 - 0.5 * mu * g * t1 * t1 + v1 * (T - t1),
                 endA.position.x - a.position.x});
    m.push_back({a.name + " rolling speed", "m/s", v1, endA.linearVelocity.x});
  } else if (name_ == "free_flight") {
    m.push_back({a.name + " x at T", "m", a.position.x + v0 * T, endA.position.x});
    m.push_back({a.name + " y at T", "m", a.position.y - 0.5 * g * T * T, endA.position.y});
  } else if (name_ == "projectile_off_the_edge") {
    const double edge = s.table.centreX + 0.5 * s.table.width;
    const double h = s.table.height;  // the centre falls from h + level to level
    m.push_back({a.name + " first touches the floor at x", "m", edge + v0 * std::sqrt(2.0 * h / g),
                 landingX.value_or(std::nan(""))});
  } else if (name_ == "head_on_spheres") {
    const EntitySpec& b = entity(s, 1);
    const double e = combine(a.material, b.material).restitution;
    const double vA = (a.mass - e * b.mass) * v0 / (a.mass + b.mass);
    const double vB = (1.0 + e) * a.mass * v0 / (a.mass + b.mass);
    const double meet = (b.position.x - a.position.x - a.geometry.sizes()[0] - b.geometry.sizes()[0]) / v0;
    if (T < meet) unfit(s, "expected a duration past the impact");
    const EntityState& endB = r.entities.at(indexOf(r, b.name));
    m.push_back({a.name + " speed after impact", "m/s", vA, endA.linearVelocity.x});
    m.push_back({b.name + " speed after impact", "m/s", vB, endB.linearVelocity.x});
    m.push_back({a.name + " x at T", "m", a.position.x + v0 * meet + vA * (T - meet), endA.position.x});
    m.push_back({b.name + " x at T", "m", b.position.x + vB * (T - meet), endB.position.x});
  } else if (name_ == "cube_tips_off_the_edge") {
    if (combine(a.material, s.table.material).friction != 0.0) unfit(s, "expected a frictionless table");
    m.push_back({a.name + " centre x when it starts to tip", "m", s.table.centreX + 0.5 * s.table.width,
                 tippingX.value_or(std::nan(""))});
    m.push_back({a.name + " height at rest on the floor", "m", 0.5 * a.geometry.sizes()[0], endA.position.y});
  } else if (name_ == "stack_rides_along" || name_ == "stack_rider_slips") {
    const EntitySpec& b = entity(s, 1);
    const StackTravel d = stackTravel(v0, a.mass, b.mass, tableFriction(s, a),
                                      combine(a.material, b.material).friction, g);
    const EntityState& endB = r.entities.at(indexOf(r, b.name));
    m.push_back({a.name + " distance slid", "m", d.a, endA.position.x - a.position.x});
    m.push_back({b.name + " distance carried", "m", d.b, endB.position.x - b.position.x});
  } else if (name_ == "straight_line_transfer") {
    // B goes on for the rest of the step in every mode; A moves the whole
    // step by the rule, and in full physics stops where it met B.
    const EntitySpec& b = entity(s, 1);
    const double step = pushStep(s);
    const double gap = b.position.x - a.position.x - 0.5 * (a.geometry.sizes()[0] + b.geometry.sizes()[0]);
    if (gap < 0 || gap > step) unfit(s, "expected B ahead of A within the step");
    const EntityState& endB = r.entities.at(indexOf(r, b.name));
    m.push_back({a.name + " distance", "m", mode == SimulationMode::Bullet ? gap : step, endA.position.x - a.position.x});
    m.push_back({b.name + " distance", "m", step - gap, endB.position.x - b.position.x});
  }
  for (const AnalyticMeasure& x : m) {
    if (x.unit == "m") result.positionError = std::max(result.positionError, std::isfinite(x.error()) ? x.error() : INFINITY);
  }
  return result;
}

}  // namespace tabletop
