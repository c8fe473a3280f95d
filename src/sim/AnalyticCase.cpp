#include "sim/AnalyticCase.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/ContactMaterial.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

const char* const kNames[] = {"cube_slides_to_rest", "sphere_slip_to_roll", "free_flight", "projectile_off_the_edge",
                              "head_on_spheres"};

[[noreturn]] void unfit(const Scenario& s, const std::string& why) {
  throw std::invalid_argument(s.file + ": not the analytic case '" + s.name + "': " + why);
}

const EntitySpec& entity(const Scenario& s, std::size_t i) {
  if (i >= s.entities.size()) unfit(s, "expected " + std::to_string(i + 1) + " entities");
  return s.entities[i];
}

// The speed the scenario's first push gives its entity, m/s, along +x.
double launchSpeed(const Scenario& s) {
  for (const Action& a : s.script) {
    if (a.type != Action::Type::Push) continue;
    if (a.magnitude.kind != PushMagnitude::Kind::Impulse || a.arrow.face || a.arrow.angleDegrees != 0.0 ||
        a.arrow.entity != s.entities.front().name || a.at.value_or(0.0) != 0.0) {
      unfit(s, "expected its first action to push the first entity at t = 0 along +x (angle 0) by an impulse");
    }
    return a.magnitude.value / s.entities.front().mass;
  }
  unfit(s, "expected a push");
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

AnalyticResult AnalyticCase::run(const Scenario& s, const Settings& settings, SimulationMode mode) const {
  const double g = settings.gravity;
  const double v0 = launchSpeed(s);
  const EntitySpec& a = entity(s, 0);
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
  const double level = a.shape == ShapeKind::Sphere ? a.size.at(0) : 0.5 * a.size.at(0);
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

  AnalyticResult result;
  result.run = runScript(s, settings, *simulation, name_ == "projectile_off_the_edge" ? StepObserver(watch) : StepObserver());
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
    const double meet = (b.position.x - a.position.x - a.size.at(0) - b.size.at(0)) / v0;
    if (T < meet) unfit(s, "expected a duration past the impact");
    const EntityState& endB = r.entities.at(indexOf(r, b.name));
    m.push_back({a.name + " speed after impact", "m/s", vA, endA.linearVelocity.x});
    m.push_back({b.name + " speed after impact", "m/s", vB, endB.linearVelocity.x});
    m.push_back({a.name + " x at T", "m", a.position.x + v0 * meet + vA * (T - meet), endA.position.x});
    m.push_back({b.name + " x at T", "m", b.position.x + vB * (T - meet), endB.position.x});
  }
  for (const AnalyticMeasure& x : m) {
    if (x.unit == "m") result.positionError = std::max(result.positionError, std::isfinite(x.error()) ? x.error() : INFINITY);
  }
  return result;
}

}  // namespace tabletop
