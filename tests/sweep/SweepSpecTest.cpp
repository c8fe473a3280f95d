// The sweep spec: the runs it makes (grid order, random draws the same
// everywhere) and every bad spec refused with located lines.

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "scenario/ScenarioError.h"
#include "sweep/SweepSpec.h"

namespace tabletop {
namespace {

const std::string kShipped = std::string(TABLETOP_SOURCE_DIR) + "/scenarios";

SweepSpec load(const std::string& text) { return loadSweepText(text, "spec.json", kShipped); }

// The lines a bad spec is refused with, joined.
std::string refusal(const std::string& text) {
  try {
    load(text);
  } catch (const ScenarioError& e) {
    std::string s;
    for (const std::string& line : e.lines()) s += line + "\n";
    return s;
  }
  return "accepted";
}

const char* kGrid = R"({"version": 1, "name": "grid", "scene": "example2_two_cubes",
  "parameters": [
    {"name": "mass", "pointer": "/entities/1/mass", "values": [0.5, 1, 2]},
    {"name": "step", "pointer": "/script/0/push/step", "range": {"from": 0.5, "to": 1.0, "count": 6}}],
  "modes": ["bullet", "rules"]})";

TEST(SweepSpec, ListsAndRangesMakeAGridWithTheLastParameterFastest) {
  const SweepSpec spec = load(kGrid);
  ASSERT_EQ(spec.runs(), 18u);
  EXPECT_EQ(spec.valuesOf(0), (std::vector<nlohmann::json>{0.5, 0.5}));
  EXPECT_EQ(spec.valuesOf(1), (std::vector<nlohmann::json>{0.5, 0.6}));
  EXPECT_EQ(spec.valuesOf(6), (std::vector<nlohmann::json>{1, 0.5}));
  EXPECT_DOUBLE_EQ(spec.valuesOf(17)[1].get<double>(), 1.0);
  // The modes in compare's order, whatever order the spec gives.
  EXPECT_EQ(spec.modes, (std::vector<SimulationMode>{SimulationMode::Rules, SimulationMode::Bullet}));
  const nlohmann::json scene = nlohmann::json::parse(spec.sceneOf(7));
  EXPECT_EQ(scene["entities"][1]["mass"], 1);
  EXPECT_DOUBLE_EQ(scene["script"][0]["push"]["step"].get<double>(), 0.6);
}

TEST(SweepSpec, RandomDrawsDependOnlyOnSeedRunAndParameter) {
  const std::string text = R"({"version": 1, "name": "r", "scene": "example2_two_cubes", "samples": 500, "seed": 7,
    "parameters": [{"pointer": "/entities/0/position/0", "random": {"uniform": [-0.5, -0.2]}},
                   {"pointer": "/entities/1/mass", "random": {"normal": [1.0, 0.1]}}],
    "modes": ["rules"]})";
  const SweepSpec a = load(text), b = load(text);
  ASSERT_EQ(a.runs(), 500u);
  std::set<double> seen;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.runs(); ++i) {
    const double x = a.valuesOf(i)[0].get<double>();
    EXPECT_EQ(a.valuesOf(i), b.valuesOf(i));
    EXPECT_GE(x, -0.5);
    EXPECT_LT(x, -0.2);
    seen.insert(x);
    sum += a.valuesOf(i)[1].get<double>();
  }
  EXPECT_EQ(seen.size(), 500u);
  // The normal draws' mean within four standard errors of 1.
  EXPECT_NEAR(sum / 500.0, 1.0, 4 * 0.1 / std::sqrt(500.0));
  // Another seed, other draws.
  std::string other = text;
  other.replace(other.find("\"seed\": 7"), 9, "\"seed\": 8");
  EXPECT_NE(load(other).valuesOf(0), a.valuesOf(0));
}

TEST(SweepSpec, TheSelfContainedSpecLoadsToTheSameRuns) {
  const SweepSpec spec = load(kGrid);
  const SweepSpec again = load(spec.selfContained());
  ASSERT_EQ(again.runs(), spec.runs());
  for (std::size_t i = 0; i < spec.runs(); ++i) EXPECT_EQ(again.sceneOf(i), spec.sceneOf(i));
}

// A random sweep: run k is the random scene of seed + k, alone in full
// physics, and its spec travels whole like any other.
TEST(SweepSpec, RandomRunsAreSeedsFromTheFirstOn) {
  const SweepSpec spec = load(R"({"version": 1, "name": "r", "seed": 40, "random": {"runs": 7, "rate": 60}})");
  ASSERT_TRUE(spec.random);
  EXPECT_EQ(spec.runs(), 7u);
  EXPECT_EQ(spec.random->rate, 60.0);
  EXPECT_EQ(spec.valueNames(), std::vector<std::string>{"seed"});
  for (std::size_t i = 0; i < spec.runs(); ++i) EXPECT_EQ(spec.valuesOf(i), std::vector<nlohmann::json>{40 + i});
  EXPECT_EQ(spec.modes, std::vector<SimulationMode>{SimulationMode::Bullet});
  EXPECT_FALSE(spec.record.positions || spec.record.events || spec.record.distance);
  EXPECT_TRUE(spec.record.cost && spec.record.stateHash);
  const SweepSpec again = load(spec.selfContained());
  ASSERT_TRUE(again.random);
  EXPECT_EQ(again.runs(), 7u);
  EXPECT_EQ(again.random->rate, 60.0);
  EXPECT_EQ(again.valuesOf(6), spec.valuesOf(6));
  // Without a rate: the default settings' step.
  EXPECT_EQ(load(R"({"version": 1, "name": "r", "random": {"runs": 1}})").random->rate, 0.0);
}

TEST(SweepSpec, BadRandomSpecsAreRefusedWithLocatedLines) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"version": 1, "name": "r", "random": {"runs": 0}})", "at /random/runs: expected a whole number from 1"},
      {R"({"version": 1, "name": "r", "random": {"runs": 200000}})", "to 100000, got 200000"},
      {R"({"version": 1, "name": "r", "random": {}})", "at /random: missing required key 'runs'"},
      {R"({"version": 1, "name": "r", "random": {"runs": 2, "rate": 1e9}})",
       "spec.json:1:59: at /random/rate: expected a rate from 10 to 100000 Hz, got 1000000000"},
      {R"({"version": 1, "name": "r", "random": {"runs": 2, "rate": -60}})", "at /random/rate: expected a rate"},
      {R"({"version": 1, "name": "r", "random": {"runs": 2, "speed": 1}})", "at /random/speed: unknown key 'speed'"},
      {R"({"version": 1, "name": "r", "random": 5})", "at /random: expected an object"},
      {R"({"version": 1, "name": "r", "random": {"runs": 2}, "scene": "example2_two_cubes"})",
       "at /scene: a sweep of random scenes draws its own"},
      {R"({"version": 1, "name": "r", "random": {"runs": 2}, "parameters": []})", "at /parameters: a sweep of random"},
      {R"({"version": 1, "name": "r", "random": {"runs": 2}, "modes": ["rules"]})",
       "at /modes: expected [\"bullet\"]"},
      {R"({"version": 1, "name": "r", "random": {"runs": 2}, "record": ["positions"]})",
       "at /record: a sweep of random scenes records its checks"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string got = refusal(text);
    EXPECT_NE(got.find(expected), std::string::npos) << "spec: " << text << "\nrefused with: " << got;
  }
}

TEST(SweepSpec, BadSpecsAreRefusedWithLocatedLines) {
  // Each: a spec and what its refusal must say, line and column included.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"version\": 1,\n \"name\": \"x\", \"scene\": \"example2_two_cubes\", \"parameters\": [], \"modes\": [\"rules\"], \"bogus\": 1}",
       "spec.json:2:93: at /bogus: unknown key 'bogus'"},
      {"{\"version\": 1, \"name\": \"x\", \"scene\": \"../../etc/passwd\", \"parameters\": [], \"modes\": [\"rules\"]}",
       "at /scene: expected a shipped scene's name (letters, digits, _ - /)"},
      {"{\"version\": 1, \"name\": \"x\", \"scene\": \"example2_two_cubes\", \"parameters\": [], \"modes\": [\"fast\"]}",
       "spec.json:1:88: at /modes/0: expected one of"},
      {"{\"version\": 1, \"name\": \"x\", \"scene\": \"example2_two_cubes\", \"modes\": [\"rules\"],\n"
       " \"parameters\": [{\"pointer\": \"/entities/7/mass\", \"values\": [1]}]}",
       "spec.json:2:29: at /parameters/0/pointer: expected a place in the scene"},
      {"{\"version\": 1, \"name\": \"x\", \"scene\": \"example2_two_cubes\", \"modes\": [\"rules\"],\n"
       " \"parameters\": [{\"pointer\": \"/entities/1/mass\", \"range\": {\"from\": 1, \"to\": 2, \"count\": 20000}}]}",
       "at /parameters/0/range/count: expected a whole number from 1 to 10000, got 20000"},
      {"{\"version\": 1, \"name\": \"x\", \"scene\": \"example2_two_cubes\", \"modes\": [\"rules\"],\n"
       " \"parameters\": [{\"pointer\": \"/entities/1/mass\", \"range\": {\"from\": 1, \"to\": 2, \"count\": 1000}},\n"
       "  {\"pointer\": \"/entities/0/mass\", \"range\": {\"from\": 1, \"to\": 2, \"count\": 1000}}]}",
       "at /parameters: expected at most 100000 runs (the grid's points x samples), got 1000000"},
      // A value that makes a bad scene is refused at its parameter, naming the run.
      {"{\"version\": 1, \"name\": \"x\", \"scene\": \"example2_two_cubes\", \"modes\": [\"rules\"],\n"
       " \"parameters\": [{\"name\": \"mass\", \"pointer\": \"/entities/1/mass\", \"values\": [1, -2]}]}",
       "spec.json:2:17: at /parameters/0: run 1 (mass = -2) gives a scene that does not check: at /entities/1/mass"},
      {"{\"version\": 1, \"name\": \"x\", \"name\": \"y\"}", "at /name: expected each key once in an object"},
      {"{\"version\": 1, \"name\": \"x\", \"scene\": 3, \"parameters\": [], \"modes\": [\"rules\"]}",
       "at /scene: expected a scene"},
      {"{\"version\": 1, \"name\": \"x\", \"scene\": \"example2_two_cubes\", \"modes\": [\"rules\"],\n"
       " \"parameters\": [{\"name\": \"m\", \"pointer\": \"/entities/1/mass\", \"values\": [1]},\n"
       "  {\"name\": \"m\", \"pointer\": \"/entities/0/mass\", \"values\": [1]}]}",
       "spec.json:3:3: at /parameters/1: expected a name no other column has, got \"m\""},
      {"[1, 2", "spec.json:1:6: not valid JSON"},
      {std::string(40, '[') + std::string(40, ']'), "expected arrays and objects nested at most 32 deep"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string got = refusal(text);
    EXPECT_NE(got.find(expected), std::string::npos) << "spec: " << text << "\nrefused with: " << got;
  }
}

}  // namespace
}  // namespace tabletop
