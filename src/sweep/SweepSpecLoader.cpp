// Reads a sweep spec: every field checked and bounded, every problem
// located in the spec, and every run's scene checked before any runs.

#include <cmath>
#include <set>

#include "core/Text.h"
#include "scenario/JsonText.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "scenario/ShippedScenes.h"
#include "scenario/ValueRanges.h"
#include "sweep/SpecChecker.h"
#include "sweep/SweepSpec.h"

namespace tabletop {
namespace {

using nlohmann::json;
using sweep::SpecChecker;
using sweep::shown;

// The base scene: inline, a file beside the spec, or a shipped scene.
json baseScene(const json& j, const std::string& at, const std::string& specFile, const std::string& shipped,
               SpecChecker& c, std::string& source) {
  if (j.is_object()) {
    // An inline scene's problems are located in the spec, under /scene.
    source = specFile;
    try {
      ScenarioLoader::loadText(j.dump(), specFile);
    } catch (const ScenarioError& e) {
      for (const Problem& p : e.problems()) c.fail(at + p.path, p.message);
    }
    return j;
  }
  if (!j.is_string() || j.get_ref<const std::string&>().empty()) {
    c.fail(at, "expected a scene (a file ending in .json, a shipped scene's name, or an object), got " + shown(j));
    return json();
  }
  const std::string& s = j.get_ref<const std::string&>();
  if (endsWith(s, ".json")) {
    const std::size_t slash = specFile.rfind('/');
    source = s.front() == '/' || slash == std::string::npos ? s : specFile.substr(0, slash + 1) + s;
  } else if (sceneNameProblem(s).empty()) {
    source = shippedScenePath(shipped, s);
  } else {
    c.fail(at, "expected a shipped scene's name (letters, digits, _ - /) or a file ending in .json, got " + shown(j));
    return json();
  }
  const std::string text = readTextFile(source, ScenarioLoader::kMaxFileBytes);
  ScenarioLoader::loadText(text, source);  // its own problems, located in its own file
  return parseJsonText(text, source, ScenarioLoader::kMaxFileBytes, ScenarioLoader::kMaxDepth).root;
}

// One entry of "parameters".
SweepParameter parameter(const json& j, const std::string& at, const json& scene, SpecChecker& c) {
  SweepParameter p;
  p.at = at;
  if (!j.is_object()) {
    c.fail(at, "expected an object, got " + shown(j));
    return p;
  }
  c.onlyKeys(j, at, {"name", "pointer", "values", "range", "random"});
  if (!j.contains("pointer")) c.fail(at, "missing required key 'pointer'");
  const json pointers = j.value("pointer", json());
  if (pointers.is_array()) {
    if (pointers.empty() || pointers.size() > SweepSpec::kMaxPointers) {
      c.fail(at + "/pointer", "expected 1 to " + std::to_string(SweepSpec::kMaxPointers) + " pointers, got " +
                                  std::to_string(pointers.size()));
    } else {
      for (std::size_t k = 0; k < pointers.size(); ++k) {
        p.pointers.push_back(c.pointer(pointers[k], at + "/pointer/" + std::to_string(k), scene));
      }
    }
  } else if (!pointers.is_null()) {
    p.pointers.push_back(c.pointer(pointers, at + "/pointer", scene));
  }
  p.name = j.contains("name") ? c.name(j["name"], at + "/name") : (p.pointers.empty() ? "" : p.pointers.front());
  const int kinds = int(j.contains("values")) + int(j.contains("range")) + int(j.contains("random"));
  if (kinds != 1) {
    c.fail(at, "expected exactly one of 'values', 'range', 'random'");
  } else if (j.contains("values")) {
    const json& v = j["values"];
    if (!v.is_array() || v.empty() || v.size() > SweepSpec::kMaxValues) {
      c.fail(at + "/values",
             "expected an array of 1 to " + std::to_string(SweepSpec::kMaxValues) + " values, got " + shown(v));
    } else {
      p.values.assign(v.begin(), v.end());
    }
  } else if (j.contains("range")) {
    const json& r = j["range"];
    const std::string ra = at + "/range";
    if (!r.is_object()) {
      c.fail(ra, "expected an object {\"from\", \"to\", \"count\"}, got " + shown(r));
      return p;
    }
    c.onlyKeys(r, ra, {"from", "to", "count"});
    for (const char* key : {"from", "to", "count"}) {
      if (!r.contains(key)) c.fail(ra, std::string("missing required key '") + key + "'");
    }
    if (!r.contains("from") || !r.contains("to") || !r.contains("count")) return p;
    const bool ok = c.isNumber(r["from"], ra + "/from") & c.isNumber(r["to"], ra + "/to");
    const std::size_t n = c.count(r["count"], ra + "/count", 1, SweepSpec::kMaxValues, 0);
    if (!ok || n == 0) return p;
    const double from = r["from"].get<double>(), to = r["to"].get<double>();
    for (std::size_t k = 0; k < n; ++k)
      p.values.push_back(n == 1 ? from : from + (to - from) * double(k) / double(n - 1));
  } else {
    const json& r = j["random"];
    const std::string ra = at + "/random";
    const bool uniform = r.is_object() && r.size() == 1 && r.contains("uniform");
    const bool normal = r.is_object() && r.size() == 1 && r.contains("normal");
    if (!uniform && !normal) {
      c.fail(ra, "expected {\"uniform\": [low, high]} or {\"normal\": [mean, deviation]}, got " + shown(r));
      return p;
    }
    const std::string key = uniform ? "uniform" : "normal";
    const json& v = r[key];
    if (!v.is_array() || v.size() != 2 || !c.isNumber(v[0], ra + "/" + key + "/0") ||
        !c.isNumber(v[1], ra + "/" + key + "/1")) {
      if (!v.is_array() || v.size() != 2) c.fail(ra + "/" + key, "expected two numbers, got " + shown(v));
      return p;
    }
    p.kind = uniform ? SweepParameter::Kind::Uniform : SweepParameter::Kind::Normal;
    p.a = v[0].get<double>();
    p.b = v[1].get<double>();
    if (uniform ? !(p.a <= p.b) : !(p.b >= 0.0)) {
      c.fail(ra + "/" + key, uniform ? "expected low <= high" : "expected a deviation >= 0");
    }
  }
  return p;
}

// The first parameter whose pointer the problem's path lies under.
std::string culprit(const SweepSpec& spec, const std::string& path) {
  for (const SweepParameter& p : spec.parameters) {
    for (const std::string& pointer : p.pointers) {
      if (path.compare(0, pointer.size(), pointer) == 0) return p.at;
    }
  }
  return "/scene";
}

// Every run's scene must load and keep the base's entities: a bad value is
// refused before anything runs, at the parameter that gave it.
void checkRuns(const SweepSpec& spec, SpecChecker& c) {
  for (std::size_t i = 0; i < spec.runs(); ++i) {
    std::string why;
    std::string at = "/parameters";
    try {
      const Scenario s = ScenarioLoader::loadText(spec.sceneOf(i), "run");
      bool same = s.entities.size() == spec.entities.size();
      for (std::size_t k = 0; same && k < s.entities.size(); ++k) same = s.entities[k].name == spec.entities[k];
      if (!same) why = "changes the scene's entities";
    } catch (const ScenarioError& e) {
      const Problem& p = e.problems().front();
      at = culprit(spec, p.path);
      why = "gives a scene that does not check: at " + p.path + ": " + p.message;
    }
    if (why.empty()) continue;
    std::string values;
    const std::vector<json> v = spec.valuesOf(i);
    for (std::size_t k = 0; k < v.size(); ++k)
      values += (k ? ", " : "") + spec.parameters[k].name + " = " + shown(v[k]);
    c.fail(at, "run " + std::to_string(i) + " (" + values + ") " + why);
    return;
  }
}

// "modes": each once, kept in compare's order (rules, compat, bullet).
std::vector<SimulationMode> modes(const json& m, SpecChecker& c) {
  std::set<SimulationMode> chosen;
  if (!m.is_array() || m.empty() || m.size() > 3) {
    c.fail("/modes", "expected 1 to 3 of \"rules\", \"compat\", \"bullet\", got " + shown(m));
    return {};
  }
  for (std::size_t k = 0; k < m.size(); ++k) {
    const auto mode = m[k].is_string() ? simulationModeFromString(m[k].get<std::string>()) : std::nullopt;
    if (!mode || !chosen.insert(*mode).second) {
      c.fail("/modes/" + std::to_string(k),
             "expected one of \"rules\", \"compat\", \"bullet\", each once, got " + shown(m[k]));
    }
  }
  std::vector<SimulationMode> out;
  for (SimulationMode mode : kAllModes) {
    if (chosen.count(mode)) out.push_back(mode);
  }
  return out;
}

// "record": what each row records.
SweepRecord record(const json& r, SpecChecker& c) {
  SweepRecord out{false, false, false, false, false};
  if (!r.is_array() || r.size() > 5) {
    c.fail("/record", "expected an array of what to record, got " + shown(r));
    return out;
  }
  for (std::size_t k = 0; k < r.size(); ++k) {
    const std::string what = r[k].is_string() ? r[k].get<std::string>() : "";
    bool* flag = what == "positions"    ? &out.positions
                 : what == "events"     ? &out.events
                 : what == "distance"   ? &out.distance
                 : what == "cost"       ? &out.cost
                 : what == "state_hash" ? &out.stateHash
                                        : nullptr;
    if (flag)
      *flag = true;
    else
      c.fail("/record/" + std::to_string(k),
             "expected one of \"positions\", \"events\", \"distance\", \"cost\", \"state_hash\", got " + shown(r[k]));
  }
  return out;
}

// "random": the random stability runs in place of a scene and parameters
// (SweepRandom): run in full physics alone, recording their checks and,
// as asked, cost and state_hash.
void readRandom(const json& root, SweepSpec& spec, SpecChecker& c) {
  for (const char* key : {"scene", "set", "parameters", "samples"}) {
    if (root.contains(key)) c.fail(std::string("/") + key, "a sweep of random scenes draws its own; remove this key");
  }
  if (spec.modes.size() > 1 || (spec.modes.size() == 1 && spec.modes.front() != SimulationMode::Bullet)) {
    c.fail("/modes", "expected [\"bullet\"]: the random runs are judged in full physics");
  }
  spec.modes = {SimulationMode::Bullet};
  if (!root.contains("record")) spec.record = SweepRecord{false, false, false, true, true};
  if (spec.record.positions || spec.record.events || spec.record.distance) {
    c.fail("/record", "a sweep of random scenes records its checks, \"cost\" and \"state_hash\" only");
  }
  const json& r = root["random"];
  if (!r.is_object()) {
    c.fail("/random", "expected an object {\"runs\", \"rate\"}, got " + shown(r));
    return;
  }
  c.onlyKeys(r, "/random", {"runs", "rate"});
  SweepRandom random;
  if (!r.contains("runs")) c.fail("/random", "missing required key 'runs'");
  else random.runs = c.count(r["runs"], "/random/runs", 1, SweepSpec::kMaxRuns, 0);
  if (r.contains("rate") && c.isNumber(r["rate"], "/random/rate")) {
    random.rate = r["rate"].get<double>();
    if (!(random.rate > 0) || !ranges::inRange(1.0 / random.rate, ranges::kTimestep)) {
      c.fail("/random/rate", "expected a rate from " + ranges::number(1.0 / ranges::kTimestep.hi) + " to " +
                                 ranges::number(1.0 / ranges::kTimestep.lo) + " Hz, got " + shown(r["rate"]));
    }
  }
  spec.random = random;
}

SweepSpec read(const json& root, const std::string& source, const std::string& shipped, bool checkEveryRun,
               SpecChecker& c) {
  SweepSpec spec;
  spec.file = source;
  if (!root.is_object()) {
    c.fail("", "expected an object, got " + shown(root));
    return spec;
  }
  c.onlyKeys(root, "",
             {"version", "name", "description", "scene", "set", "parameters", "samples", "seed", "modes", "record",
              "random"});
  const bool random = root.contains("random");
  for (const char* key : {"version", "name", "scene", "parameters", "modes"}) {
    if (!root.contains(key) && !(random && std::string(key) != "version" && std::string(key) != "name")) {
      c.fail("", std::string("missing required key '") + key + "'");
    }
  }
  if (root.contains("version") && root["version"] != 1) c.fail("/version", "expected 1, got " + shown(root["version"]));
  if (root.contains("name")) spec.name = c.name(root["name"], "/name");
  if (root.contains("description") &&
      !(root["description"].is_string() && root["description"].get_ref<const std::string&>().size() <= 4096)) {
    c.fail("/description", "expected a string of at most 4096 bytes, got " + shown(root["description"]));
  }
  if (root.contains("samples")) spec.samples = c.count(root["samples"], "/samples", 1, SweepSpec::kMaxRuns, 1);
  if (root.contains("seed")) {
    if (root["seed"].is_number_unsigned())
      spec.seed = root["seed"].get<std::uint64_t>();
    else
      c.fail("/seed", "expected a whole number from 0 to 2^64 - 1, got " + shown(root["seed"]));
  }
  if (root.contains("modes")) spec.modes = modes(root["modes"], c);
  if (root.contains("record")) spec.record = record(root["record"], c);
  if (random) {
    readRandom(root, spec, c);
    return spec;
  }
  if (root.contains("scene")) spec.scene = baseScene(root["scene"], "/scene", source, shipped, c, spec.sceneSource);
  if (!spec.scene.is_object()) return spec;
  // Each run's scene is built from the base's text: its size bounds the
  // cost of checking every run before any runs.
  if (const std::size_t bytes = spec.scene.dump().size(); bytes > SweepSpec::kMaxSceneBytes) {
    c.fail("/scene", "expected a base scene of at most " + std::to_string(SweepSpec::kMaxSceneBytes) +
                         " bytes as JSON, got " + std::to_string(bytes));
  }
  spec.entities.clear();
  for (const json& e : spec.scene.value("entities", json::array())) spec.entities.push_back(e.value("name", ""));
  if (spec.entities.size() > SweepSpec::kMaxEntities) {
    c.fail("/scene", "expected a scene of at most " + std::to_string(SweepSpec::kMaxEntities) + " entities, got " +
                         std::to_string(spec.entities.size()));
  }
  if (root.contains("set")) {
    const json& set = root["set"];
    if (!set.is_object() || set.size() > SweepSpec::kMaxPointers) {
      c.fail("/set", "expected an object of at most " + std::to_string(SweepSpec::kMaxPointers) +
                         " pointers and their values, got " + shown(set));
    } else {
      for (auto it = set.begin(); it != set.end(); ++it) {
        const std::string at = "/set/" + escapePointerToken(it.key());
        const std::size_t before = c.problems.size();
        c.pointer(json(it.key()), at, spec.scene);
        if (c.problems.size() != before) continue;
        const json::json_pointer p(it.key());
        if (!it->is_null()) {
          spec.scene[p] = *it;
          continue;
        }
        // null removes a key (to give a push an angle in place of a direction).
        json& parent = spec.scene[p.parent_pointer()];
        if (parent.is_object())
          parent.erase(p.back());
        else
          c.fail(at, "expected a key of an object to remove (null), got an element of an array");
      }
    }
  }
  if (root.contains("parameters")) {
    const json& ps = root["parameters"];
    if (!ps.is_array() || ps.size() > SweepSpec::kMaxParameters) {
      c.fail("/parameters", "expected an array of at most " + std::to_string(SweepSpec::kMaxParameters) +
                                " parameters, got " + shown(ps));
    } else {
      for (std::size_t k = 0; k < ps.size(); ++k)
        spec.parameters.push_back(parameter(ps[k], "/parameters/" + std::to_string(k), spec.scene, c));
    }
  }
  // Each parameter names a column of its own.
  std::set<std::string> names{"run", "problem"};
  for (const SweepParameter& p : spec.parameters) {
    const bool modeLike =
        p.name.rfind("rules.", 0) == 0 || p.name.rfind("compat.", 0) == 0 || p.name.rfind("bullet.", 0) == 0;
    if (!names.insert(p.name).second || modeLike) {
      c.fail(p.at, "expected a name no other column has, got \"" + shownText(p.name, 40) + "\"");
    }
  }
  if (!c.problems.empty()) return spec;
  // The run count, bounded before anything multiplies past it.
  double runs = static_cast<double>(spec.samples);
  for (const SweepParameter& p : spec.parameters) {
    if (p.kind == SweepParameter::Kind::List) runs *= static_cast<double>(p.values.size());
  }
  if (runs > static_cast<double>(SweepSpec::kMaxRuns)) {
    c.fail("/parameters", "expected at most " + std::to_string(SweepSpec::kMaxRuns) +
                              " runs (the grid's points x samples), got " + fixed(runs, 0));
    return spec;
  }
  if (checkEveryRun) checkRuns(spec, c);
  return spec;
}

}  // namespace

SweepSpec loadSweepText(const std::string& text, const std::string& source, const std::string& shippedScenes,
                        bool checkEveryRun) {
  JsonText parsed = parseJsonText(text, source, SweepSpec::kMaxFileBytes, SweepSpec::kMaxDepth);
  SpecChecker c;
  c.problems = duplicateProblems(*parsed.locator);
  SweepSpec spec = read(parsed.root, source, shippedScenes, checkEveryRun, c);
  if (!c.problems.empty()) {
    for (Problem& p : c.problems) {
      if (p.line > 0) continue;
      const JsonLocator::Location where = parsed.locator->find(p.path);
      p.line = where.line;
      p.column = where.column;
    }
    throw ScenarioError(source, std::move(c.problems));
  }
  spec.locator = std::move(parsed.locator);
  return spec;
}

SweepSpec loadSweepFile(const std::string& path, const std::string& shippedScenes) {
  return loadSweepText(readTextFile(path, SweepSpec::kMaxFileBytes), path, shippedScenes);
}

}  // namespace tabletop
