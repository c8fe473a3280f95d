#include "sim/ModeComparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Angle.h"
#include "sim/ResultFormat.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop {
namespace {

// Trajectories keep a point every this many simulated seconds.
constexpr double kSampleInterval = 1.0 / 120.0;
// A yaw difference beyond this is a rotation, degrees.
constexpr double kRotatedDegrees = 2.0;
// Coming back along the line by more than this is a bounce, metres.
constexpr double kBackDistance = 5e-3;
// An up axis tilted more than this is tipped, degrees.
constexpr double kTippedDegrees = 10.0;

bool offTable(const EntityState& s) { return s.status != EntityPositionStatus::OnTable; }

// The cosine of the tilt of the body's up axis from +Y.
double upright(const std::array<double, 4>& q) {
  const double x = q[1], z = q[3];
  return 1.0 - 2.0 * (x * x + z * z);
}

double yawDifference(double a, double b) {
  double d = std::fmod(a - b, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d < -180.0) d += 360.0;
  return std::abs(d);
}

std::optional<DirectionDef> firstEdge(const RunResult& run, const std::string& entity) {
  for (const Event& e : run.events) {
    if (e.type == EventType::LeavesTable && e.entity == entity) return e.edge;
  }
  return {};
}

}  // namespace

std::string verdict(const Vec3& start, const ModeOutcome& rules, const ModeOutcome& other) {
  const EntityState& r = rules.state;
  const EntityState& o = other.state;
  if (offTable(r) != offTable(o)) return std::string("diverges: ") + (offTable(o) ? "slid off" : "stayed behind");
  if (offTable(r)) return rules.edge == other.edge ? "agrees" : "diverges: dropped from another edge";
  // Every reason that applies, with how many times its threshold it is.
  std::vector<std::pair<double, const char*>> reasons;
  const auto beyond = [&reasons](double amount, double threshold, const char* reason) {
    if (amount > threshold) reasons.emplace_back(amount / threshold, reason);
  };
  // A sphere's orientation is no outcome: it rolls.
  if (o.shape != ShapeKind::Sphere) {
    const double tilt = std::acos(std::clamp(upright(o.orientation), -1.0, 1.0)) * 180.0 / kPi;
    beyond(tilt, kTippedDegrees, "tipped");
    beyond(yawDifference(o.yawDegrees, r.yawDegrees), kRotatedDegrees, "rotated");
  }
  if (other.fromRules > kAgreeDistance) {
    const Vec3 ruleMove = r.position - start;
    const Vec3 move = o.position - start;
    const double ruleLength = std::hypot(ruleMove.x, ruleMove.z);
    if (ruleLength > kAgreeDistance) {
      const Vec3 along = ruleMove * (1.0 / ruleLength);
      const double ahead = move.x * along.x + move.z * along.z;
      const double side = std::abs(move.x * along.z - move.z * along.x);
      // Bounced back: it got further along the rules' line than where it ended.
      double furthest = ahead;
      for (const Vec3& p : other.trajectory.points) {
        furthest = std::max(furthest, (p.x - start.x) * along.x + (p.z - start.z) * along.z);
      }
      beyond(furthest - ahead, kBackDistance, "bounced back");
      beyond(side, kAgreeDistance, "went sideways");
      beyond(std::abs(ahead - ruleLength), kAgreeDistance, ahead < ruleLength ? "stopped short" : "went further");
    } else {
      beyond(other.fromRules, kAgreeDistance, "went sideways");
    }
  }
  if (reasons.empty()) return "agrees";
  // The largest first.
  std::stable_sort(reasons.begin(), reasons.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string out = "diverges: ";
  for (std::size_t k = 0; k < reasons.size(); ++k) out += (k ? ", " : "") + std::string(reasons[k].second);
  return out;
}

RecordedRun runRecorded(const Scenario& scenario, const Settings& settings, SimulationMode mode,
                        const StepObserver& afterStep) {
  RecordedRun out;
  std::unique_ptr<Simulation> sim = buildSimulation(scenario, settings, mode);
  out.paths.resize(scenario.entities.size());
  const auto record = [&out](const Simulation& s) {
    const std::vector<EntityState> states = s.snapshot();
    for (std::size_t i = 0; i < states.size(); ++i) out.paths[i].points.push_back(states[i].position);
  };
  record(*sim);
  double next = kSampleInterval;
  out.run = runScript(scenario, settings, *sim, [&](const Simulation& s) {
    if (afterStep) afterStep(s);
    if (s.time() + 1e-12 < next) return;
    next += kSampleInterval;
    record(s);
  });
  record(*sim);
  return out;
}

std::vector<ModeOutcome> againstRules(const Scenario& scenario, const RecordedRun& rules, RecordedRun other) {
  std::vector<ModeOutcome> outcomes(scenario.entities.size());
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    const std::string& name = scenario.entities[i].name;
    ModeOutcome reference;
    reference.state = rules.run.entities[i];
    reference.edge = firstEdge(rules.run, name);
    ModeOutcome& out = outcomes[i];
    out.state = other.run.entities[i];
    out.edge = firstEdge(other.run, name);
    out.trajectory = std::move(other.paths[i]);
    out.fromRules = (out.state.position - reference.state.position).length();
    out.verdict = verdict(rules.paths[i].points.front(), reference, out);
  }
  return outcomes;
}

Comparison compareModes(const Scenario& scenario, const Settings& settings, const StepObserver& afterStep) {
  Comparison c;
  c.scenario = scenario.name;
  c.file = scenario.file;
  std::array<RecordedRun, 3> recorded;
  for (std::size_t m = 0; m < 3; ++m) recorded[m] = runRecorded(scenario, settings, kAllModes[m], afterStep);
  for (std::size_t m = 0; m < 3; ++m) c.runs[m] = recorded[m].run;
  std::array<std::vector<ModeOutcome>, 3> outcomes;
  for (std::size_t m = 1; m < 3; ++m) outcomes[m] = againstRules(scenario, recorded[0], std::move(recorded[m]));
  for (std::size_t i = 0; i < scenario.entities.size(); ++i) {
    EntityComparison e;
    e.name = scenario.entities[i].name;
    e.start = recorded[0].paths[i].points.front();
    e.modes[0].state = c.runs[0].entities[i];
    e.modes[0].edge = firstEdge(c.runs[0], e.name);
    e.modes[0].trajectory = std::move(recorded[0].paths[i]);
    e.modes[0].verdict = "reference";
    for (std::size_t m = 1; m < 3; ++m) e.modes[m] = std::move(outcomes[m][i]);
    c.entities.push_back(std::move(e));
  }
  return c;
}

std::string formatComparison(const Comparison& c) {
  std::string s = c.scenario + "  (" + c.file + ")\n";
  s += "  rules, compat and bullet; distances from the rules' final centre; on-table centres within " +
       fixed(kAgreeDistance * 1000.0, 1) + " mm agree\n";
  std::size_t width = 8;
  for (const EntityComparison& e : c.entities) width = std::max(width, e.name.size() + 2);
  s += "  " + padded("entity", width) + padded("mode", 8) + padded("x [m]", 9) + padded("y [m]", 9) +
       padded("z [m]", 9) + padded("yaw [deg]", 10) + padded("status", 22) + padded("from rules [m]", 16) +
       "verdict\n";
  for (const RunResult& r : c.runs) {
    if (!r.complete) s += "  INCOMPLETE in mode " + r.mode + ", the run stopped: " + r.failure + "\n";
  }
  for (const EntityComparison& e : c.entities) {
    for (std::size_t m = 0; m < 3; ++m) {
      const ModeOutcome& o = e.modes[m];
      const Vec3& p = o.state.position;
      s += "  " + padded(m == 0 ? e.name : "", width) + padded(std::string(toString(kAllModes[m])), 8) +
           padded(fixed(p.x, 4), 9) + padded(fixed(p.y, 4), 9) + padded(fixed(p.z, 4), 9) +
           padded(fixed(o.state.yawDegrees, 1), 10) + padded(std::string(toString(o.state.status)), 22) +
           padded(m == 0 ? "" : fixed(o.fromRules, 4), 16) + o.verdict + "\n";
    }
  }
  return s;
}

nlohmann::json comparisonJson(const Comparison& c) {
  nlohmann::json entities = nlohmann::json::array();
  for (const EntityComparison& e : c.entities) {
    nlohmann::json j{{"name", e.name}, {"start", {e.start.x, e.start.y, e.start.z}}};
    for (std::size_t m = 0; m < 3; ++m) {
      const ModeOutcome& o = e.modes[m];
      const Vec3& p = o.state.position;
      nlohmann::json mode{{"position", {p.x, p.y, p.z}},
                          {"yaw", o.state.yawDegrees},
                          {"status", toString(o.state.status)},
                          {"support", o.state.support.name()},
                          {"verdict", o.verdict}};
      if (o.edge) mode["edge"] = toString(*o.edge);
      if (m > 0) mode["distance_from_rules"] = o.fromRules;
      j[std::string(toString(kAllModes[m]))] = mode;
    }
    entities.push_back(j);
  }
  nlohmann::json hashes;
  for (std::size_t m = 0; m < 3; ++m) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(c.runs[m].stateHash));
    hashes[std::string(toString(kAllModes[m]))] = hex;
  }
  nlohmann::json j{{"scenario", c.scenario}, {"file", c.file}, {"agree_distance", kAgreeDistance},
                   {"entities", entities}, {"state_hash", hashes}};
  for (const RunResult& r : c.runs) {
    if (!r.complete) j["failures"][r.mode] = r.failure;
  }
  return j;
}

}  // namespace tabletop
