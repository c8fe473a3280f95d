#include "measure/ToleranceFront.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scenario/ScenarioError.h"
#include "measure/AnalyticCase.h"

namespace tabletop {
namespace {

std::string describe(const ToleranceFront::Point& p) {
  char text[160];
  std::snprintf(text, sizeof text, "%.0f Hz, %d iterations, %s (error %.4g mm, %.3g ms per simulated second)",
                1.0 / p.timestep, p.iterations, std::string(toString(p.integrator)).c_str(), 1000.0 * p.error,
                p.costMs);
  return text;
}

}  // namespace

std::vector<std::string> motionsOf(const Scenario& scene) {
  bool sliding = false, rolling = false, stacked = false;
  for (const EntitySpec& e : scene.entities) {
    (e.geometry.kind() == ShapeKind::Sphere ? rolling : sliding) = true;
    if (e.on.isEntity()) stacked = true;
  }
  // Anything pushed far enough leaves the table and flies to the floor.
  std::vector<std::string> motions{"flight", "leaving the table"};
  if (sliding) motions.push_back("sliding");
  if (rolling) motions.push_back("rolling");
  if (scene.entities.size() > 1) motions.push_back("collision");
  if (stacked) motions.push_back("stacking");
  return motions;
}

ToleranceFront ToleranceFront::fromBench(const std::vector<BenchPoint>& points) {
  // The fronts of full physics alone (the bench's own fronts also hold
  // the other modes).
  std::vector<BenchPoint> bullet;
  for (const BenchPoint& p : points) {
    if (p.mode == SimulationMode::Bullet && !AnalyticCase::motion(p.scene).empty()) bullet.push_back(p);
  }
  markParetoFronts(bullet);
  ToleranceFront f;
  for (const BenchPoint& p : bullet) {
    if (p.front) f.cases_[p.scene].push_back({p.timestep, p.iterations, p.integrator, p.costMs, p.error});
  }
  for (auto& [name, front] : f.cases_) {
    std::sort(front.begin(), front.end(), [](const Point& a, const Point& b) { return a.costMs < b.costMs; });
  }
  return f;
}

std::string ToleranceFront::toJson() const {
  nlohmann::json cases = nlohmann::json::object();
  for (const auto& [name, front] : cases_) {
    nlohmann::json points = nlohmann::json::array();
    for (const Point& p : front) {
      points.push_back({{"timestep", p.timestep}, {"iterations", p.iterations},
                        {"integrator", toString(p.integrator)}, {"cost_ms_per_s", p.costMs}, {"error_m", p.error}});
    }
    cases[name] = {{"motion", AnalyticCase::motion(name)}, {"front", points}};
  }
  const nlohmann::json all = {
      {"version", 1},
      {"made_by", "tabletop bench --modes bullet --write-front FILE"},
      {"about", "per analytic case, the full-physics settings no other beats in both cost and error"},
      {"cases", cases}};
  return all.dump(2) + "\n";
}

ToleranceFront ToleranceFront::load(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw ScenarioError(file, {{"", "cannot read the front file"}});
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw ScenarioError(file, {{"", std::string("expected JSON: ") + e.what()}});
  }
  const auto expect = [&file](bool ok, const std::string& where, const std::string& what) {
    if (!ok) throw ScenarioError(file, {{where, "expected " + what}});
  };
  expect(j.is_object() && j.value("version", 0) == 1, "/version", "1");
  expect(j.contains("cases") && j["cases"].is_object(), "/cases", "an object of cases");
  ToleranceFront f;
  for (const auto& [name, c] : j["cases"].items()) {
    const std::string at = "/cases/" + name;
    expect(!AnalyticCase::motion(name).empty(), at, "the name of an analytic case");
    expect(c.is_object() && c.contains("front") && c["front"].is_array() && !c["front"].empty(), at + "/front",
           "a non-empty array of settings");
    for (std::size_t i = 0; i < c["front"].size(); ++i) {
      const nlohmann::json& p = c["front"][i];
      const std::string pat = at + "/front/" + std::to_string(i);
      const auto number = [&](const char* key, double lo, double hi) {
        expect(p.is_object() && p.contains(key) && p[key].is_number() && p[key].get<double>() >= lo &&
                   p[key].get<double>() <= hi,
               pat + "/" + key, "a number from " + std::to_string(lo) + " to " + std::to_string(hi));
        return p[key].get<double>();
      };
      Point q;
      q.timestep = number("timestep", kMinTimestep, kMaxTimestep);
      q.iterations = static_cast<int>(number("iterations", 1, 10000));
      q.costMs = number("cost_ms_per_s", 0, 1e9);
      q.error = number("error_m", 0, 1e9);
      const std::optional<Integrator> integrator =
          p.contains("integrator") && p["integrator"].is_string()
              ? integratorFromString(p["integrator"].get<std::string>())
              : std::nullopt;
      expect(integrator.has_value(), pat + "/integrator", "\"euler\" or \"trapezoid\"");
      q.integrator = *integrator;
      f.cases_[name].push_back(q);
    }
    std::sort(f.cases_[name].begin(), f.cases_[name].end(),
              [](const Point& a, const Point& b) { return a.costMs < b.costMs; });
  }
  expect(!f.cases_.empty(), "/cases", "at least one case");
  return f;
}

ToleranceChoice ToleranceFront::choose(const Scenario& scene, double tolerance) const {
  ToleranceChoice choice;
  choice.settings = scene.settings;
  std::optional<Point> finest;
  int iterations = 1;
  bool trapezoid = false;
  for (const std::string& motion : motionsOf(scene)) {
    for (const auto& [name, front] : cases_) {
      if (AnalyticCase::motion(name) != motion) continue;
      const auto meets = std::find_if(front.begin(), front.end(), [&](const Point& p) { return p.error <= tolerance; });
      Point pick;
      if (meets != front.end()) {
        pick = *meets;
        choice.reasons.push_back(motion + " (" + name + "): " + describe(pick));
      } else {
        pick = *std::min_element(front.begin(), front.end(),
                                 [](const Point& a, const Point& b) { return a.error < b.error; });
        choice.met = false;
        choice.reasons.push_back(motion + " (" + name + "): no measured setting is within the tolerance; the most "
                                 "accurate is " + describe(pick));
      }
      iterations = std::max(iterations, pick.iterations);
      trapezoid = trapezoid || pick.integrator == Integrator::Trapezoid;
      if (!finest || pick.timestep < finest->timestep) finest = pick;
    }
  }
  if (finest) {
    choice.settings.timestep = finest->timestep;
    choice.settings.iterations = iterations;
    choice.settings.integrator = trapezoid ? Integrator::Trapezoid : Integrator::Euler;
  } else {
    choice.met = false;
    choice.reasons.push_back("the front holds no case for this scene's motions; the scene's own settings are kept");
  }
  return choice;
}

}  // namespace tabletop
