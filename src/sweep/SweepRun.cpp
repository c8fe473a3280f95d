#include "sweep/SweepRun.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/StateHash.h"
#include "measure/RandomRunCheck.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "sim/ModeComparison.h"
#include "sim/ResultFormat.h"

namespace tabletop {
namespace {

using nlohmann::json;

bool comparesWithRules(const SweepSpec& spec, SimulationMode m) {
  return spec.record.distance && m != SimulationMode::Rules && spec.modes.front() == SimulationMode::Rules;
}

std::string prefix(SimulationMode m) { return std::string(toString(m)) + "."; }

// Each event on one line of text: "0.175 s contact begins between A and B; ...".
std::string eventsText(const RunResult& run) {
  std::string s;
  for (const Event& e : run.events) s += (s.empty() ? "" : "; ") + fixed(e.t, 3) + " s " + describe(e);
  return s;
}

// A mode's cells, in the order of sweepColumns().
void modeCells(const SweepSpec& spec, SimulationMode m, const RecordedRun& run, const std::vector<ModeOutcome>* vsRules,
               SweepRow& row) {
  if (spec.record.positions) {
    for (const EntityState& e : run.run.entities) {
      row.insert(row.end(), {e.position.x, e.position.y, e.position.z, e.yawDegrees, std::string(toString(e.status))});
    }
  }
  if (spec.record.events) row.push_back(eventsText(run.run));
  if (comparesWithRules(spec, m)) {
    double distance = 0.0;
    std::string reason;
    for (const ModeOutcome& o : *vsRules) {
      row.insert(row.end(), {o.fromRules, o.verdict});
      if (o.verdict != "agrees" && (reason.empty() || o.fromRules > distance)) reason = firstReason(o.verdict);
      distance = std::max(distance, o.fromRules);
    }
    row.insert(row.end(), {distance, reason.empty(), reason});
  }
  if (spec.record.cost) row.push_back(run.run.wallSeconds);
  if (spec.record.stateHash) row.push_back(formatHash(run.run.stateHash));
  row.push_back(run.run.failure);
}

// JSON has no NaN: a diverged run's non-finite numbers are null, so a row
// reads the same whichever process computed it.
SweepRow finiteOrNull(SweepRow row) {
  for (json& v : row) {
    if (v.is_number_float() && !std::isfinite(v.get<double>())) v = nullptr;
  }
  return row;
}

// The random runs' columns after "run" and "seed" (SweepRandom).
std::vector<std::string> randomColumns(const SweepSpec& spec) {
  std::vector<std::string> c{"bodies", "pushes"};
  for (const char* what : {"stable", "reason", "under_floor_m", "farthest_m", "reach_m", "energy_excess_J",
                           "energy_gain_J", "energy_scale_J"}) {
    c.push_back(std::string("bullet.") + what);
  }
  if (spec.record.cost) c.push_back("bullet.wall_s");
  if (spec.record.stateHash) c.push_back("bullet.state_hash");
  c.insert(c.end(), {"bullet.failure", "problem"});
  return c;
}

// A random run's row: its check (measure/RandomRunCheck.h), cell by cell.
SweepRow randomRow(const SweepSpec& spec, std::size_t index, const StepObserver& afterStep) {
  const RandomRunCheck c = checkRandomRun(spec.seed + index, spec.random->rate > 0 ? 1.0 / spec.random->rate : 0.0,
                                          afterStep);
  const StabilityReport& r = c.report;
  SweepRow row{index, c.seed, c.bodies, c.pushes, c.stable(), c.reason, c.underFloor, r.farthest, c.reach,
               r.energyExcess, r.energyGain, r.energyScale};
  if (spec.record.cost) row.push_back(r.wallSeconds);
  if (spec.record.stateHash) row.push_back(formatHash(r.stateHash));
  row.insert(row.end(), {r.failure, ""});
  return row;
}

}  // namespace

std::vector<std::string> sweepColumns(const SweepSpec& spec) {
  std::vector<std::string> c{"run"};
  for (const std::string& name : spec.valueNames()) c.push_back(name);
  if (spec.random) {
    const std::vector<std::string> rest = randomColumns(spec);
    c.insert(c.end(), rest.begin(), rest.end());
    return c;
  }
  for (SimulationMode m : spec.modes) {
    const std::string mode = prefix(m);
    if (spec.record.positions) {
      for (const std::string& e : spec.entities) {
        for (const char* what : {".x", ".y", ".z", ".yaw", ".status"}) c.push_back(mode + e + what);
      }
    }
    if (spec.record.events) c.push_back(mode + "events");
    if (comparesWithRules(spec, m)) {
      for (const std::string& e : spec.entities) {
        c.push_back(mode + e + ".from_rules");
        c.push_back(mode + e + ".verdict");
      }
      for (const char* what : {"distance", "agrees", "reason"}) c.push_back(mode + what);
    }
    if (spec.record.cost) c.push_back(mode + "wall_s");
    if (spec.record.stateHash) c.push_back(mode + "state_hash");
    c.push_back(mode + "failure");
  }
  c.push_back("problem");
  return c;
}

bool isTimingColumn(const std::string& column) { return endsWith(column, ".wall_s"); }

std::string firstReason(const std::string& verdict) {
  const std::string head = "diverges: ";
  if (verdict.compare(0, head.size(), head) != 0) return "";
  return verdict.substr(head.size(), verdict.find(',') == std::string::npos ? std::string::npos
                                                                             : verdict.find(',') - head.size());
}

SweepRow runSweepRow(const SweepSpec& spec, std::size_t index, const StepObserver& afterStep) {
  if (spec.random) return finiteOrNull(randomRow(spec, index, afterStep));
  SweepRow row{index};
  for (json& v : spec.valuesOf(index)) row.push_back(std::move(v));
  const std::size_t width = sweepColumns(spec).size();
  try {
    // The scene was checked when the spec was loaded; a mode may still
    // refuse it (bodies overlapping at the start).
    const Scenario scenario = ScenarioLoader::loadText(spec.sceneOf(index), spec.sceneSource);
    std::vector<RecordedRun> runs;
    for (SimulationMode m : spec.modes) runs.push_back(runRecorded(scenario, scenario.settings, m, afterStep));
    for (std::size_t k = 0; k < spec.modes.size(); ++k) {
      std::optional<std::vector<ModeOutcome>> vsRules;
      if (comparesWithRules(spec, spec.modes[k])) vsRules = againstRules(scenario, runs.front(), runs[k]);
      modeCells(spec, spec.modes[k], runs[k], vsRules ? &*vsRules : nullptr, row);
    }
    row.push_back("");
  } catch (const ScenarioError& e) {
    // The row keeps its width: the modes' cells empty, the problem said.
    row.resize(width - 1, json());
    row.push_back(e.problems().empty() ? std::string(e.what()) : e.problems().front().message);
  }
  return finiteOrNull(row);
}

}  // namespace tabletop
