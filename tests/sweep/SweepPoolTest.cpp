// The runs of a sweep: rows the same whichever process computed them and
// however many workers ran, the comparison with the rules as compare's.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/StateHash.h"
#include "measure/RandomRunCheck.h"
#include "sim/ModeComparison.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "sweep/SweepPool.h"
#include "sweep/SweepRun.h"

namespace tabletop {
namespace {

const std::string kShipped = std::string(TABLETOP_SOURCE_DIR) + "/scenarios";

// Example 2 with B's mass and the push's step varied: 12 runs, in the
// rules and in full physics.
SweepSpec example2Sweep() {
  return loadSweepText(R"({"version": 1, "name": "ex2", "scene": "example2_two_cubes",
    "parameters": [{"name": "mass", "pointer": "/entities/1/mass", "values": [0.25, 0.5, 1.0]},
                   {"name": "step", "pointer": "/script/0/push/step", "range": {"from": 0.5, "to": 1.1, "count": 4}}],
    "modes": ["rules", "bullet"]})",
                       "ex2.json", kShipped);
}

// The rows without their wall times, which differ from run to run.
std::vector<SweepRow> withoutTimes(const SweepSpec& spec, std::vector<SweepRow> rows) {
  const std::vector<std::string> columns = sweepColumns(spec);
  for (SweepRow& row : rows) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (isTimingColumn(columns[c])) row[c] = nullptr;
    }
  }
  return rows;
}

std::vector<SweepRow> runAll(const SweepSpec& spec, int jobs, std::size_t first = 0) {
  std::vector<SweepRow> rows;
  runSweepPool(spec, first, spec.runs() - first, jobs, [&rows](const SweepRow& r) { rows.push_back(r); },
               [] { return false; });
  return withoutTimes(spec, rows);
}

TEST(SweepPool, TheTableIsTheSameRowForRowWhateverTheJobs) {
  const SweepSpec spec = example2Sweep();
  const std::vector<SweepRow> one = runAll(spec, 1);
  ASSERT_EQ(one.size(), 12u);
  for (std::size_t i = 0; i < one.size(); ++i) EXPECT_EQ(one[i][0], i);
  EXPECT_EQ(runAll(spec, 2), one);
  EXPECT_EQ(runAll(spec, 5), one);
  // A part of the sweep, from run 7 on, is the same part.
  EXPECT_EQ(runAll(spec, 3, 7), std::vector<SweepRow>(one.begin() + 7, one.end()));
  // The runs differ from each other: the hashes are of real runs.
  const std::vector<std::string> columns = sweepColumns(spec);
  const std::size_t hash = static_cast<std::size_t>(std::find(columns.begin(), columns.end(), "bullet.state_hash") - columns.begin());
  std::set<std::string> hashes;
  for (const SweepRow& row : one) hashes.insert(row.at(hash).get<std::string>());
  EXPECT_EQ(hashes.size(), one.size());
}

// The random stability runs as a sweep: each row is the check the
// hard-case test makes of its seed (measure/RandomRunCheck.h), and the
// rows are the same on one worker and on three.
TEST(SweepPool, RandomRowsAreTheirSeedsChecksWhateverTheJobs) {
  const SweepSpec spec =
      loadSweepText(R"({"version": 1, "name": "r", "seed": 100, "random": {"runs": 6, "rate": 60}})", "r", kShipped);
  const std::vector<SweepRow> one = runAll(spec, 1);
  ASSERT_EQ(one.size(), 6u);
  EXPECT_EQ(runAll(spec, 3), one);
  const std::vector<std::string> columns = sweepColumns(spec);
  ASSERT_EQ(columns.size(), one.front().size());
  const auto cell = [&columns](const SweepRow& row, const std::string& name) {
    return row.at(static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin()));
  };
  for (std::size_t i = 0; i < one.size(); ++i) {
    const RandomRunCheck c = checkRandomRun(100 + i, 1.0 / 60.0);
    EXPECT_EQ(cell(one[i], "seed"), 100 + i);
    EXPECT_EQ(cell(one[i], "bodies"), c.bodies);
    EXPECT_EQ(cell(one[i], "bullet.stable"), c.stable());
    EXPECT_EQ(cell(one[i], "bullet.energy_gain_J"), c.report.energyGain);
    EXPECT_EQ(cell(one[i], "bullet.state_hash"), formatHash(c.report.stateHash));
  }
  // Another rate is another run.
  const SweepSpec faster =
      loadSweepText(R"({"version": 1, "name": "r", "seed": 100, "random": {"runs": 1, "rate": 240}})", "r", kShipped);
  EXPECT_NE(cell(runAll(faster, 1).front(), "bullet.state_hash"), cell(one.front(), "bullet.state_hash"));
}

TEST(SweepPool, ARowComparesWithTheRulesAsCompareDoes) {
  const SweepSpec spec = example2Sweep();
  const std::vector<std::string> columns = sweepColumns(spec);
  const auto at = [&columns](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  const std::size_t run = 5;
  const SweepRow row = runSweepRow(spec, run);
  const Scenario scenario = ScenarioLoader::loadText(spec.sceneOf(run), "run");
  const Comparison c = compareModes(scenario, scenario.settings);
  double distance = 0.0;
  for (std::size_t e = 0; e < 2; ++e) {
    const ModeOutcome& bullet = c.entities[e].modes[2];
    const std::string name = c.entities[e].name;
    EXPECT_EQ(row.at(at("bullet." + name + ".verdict")), bullet.verdict);
    EXPECT_DOUBLE_EQ(row.at(at("bullet." + name + ".from_rules")).get<double>(), bullet.fromRules);
    EXPECT_DOUBLE_EQ(row.at(at("rules." + name + ".x")).get<double>(), c.entities[e].modes[0].state.position.x);
    distance = std::max(distance, bullet.fromRules);
  }
  EXPECT_DOUBLE_EQ(row.at(at("bullet.distance")).get<double>(), distance);
  EXPECT_EQ(row.at(at("problem")), "");
  EXPECT_EQ(firstReason("diverges: stopped short, rotated"), "stopped short");
  EXPECT_EQ(firstReason("agrees"), "");
}

// A run that does not start still gives a whole row, saying why: bodies
// overlapping (found when a mode builds the scene), or, in a spec a worker
// loads without checking every run, a value the scene refuses.
TEST(SweepPool, ARunThatCannotStartGivesAWholeRowWithItsProblem) {
  const auto spec = [](const std::string& pointer, const std::string& values, bool checked) {
    return loadSweepText(R"({"version": 1, "name": "bad", "scene": "example2_two_cubes",
      "parameters": [{"name": "x", "pointer": ")" + pointer + R"(", "values": )" + values + R"(}],
      "modes": ["rules", "bullet"]})",
                         "bad.json", kShipped, checked);
  };
  const SweepSpec overlapping = spec("/entities/1/position/0", "[0.2, -0.3]", true);  // run 1: B on A
  const SweepRow good = runSweepRow(overlapping, 0), bad = runSweepRow(overlapping, 1);
  ASSERT_EQ(bad.size(), sweepColumns(overlapping).size());
  EXPECT_EQ(good.back(), "");
  EXPECT_NE(bad.back().get<std::string>().find("overlaps"), std::string::npos) << bad.back();
  EXPECT_TRUE(bad.at(2).is_null());

  EXPECT_THROW(spec("/entities/1/mass", "[1, -2]", true), ScenarioError);
  const SweepSpec unchecked = spec("/entities/1/mass", "[1, -2]", false);
  const SweepRow refused = runSweepRow(unchecked, 1);
  ASSERT_EQ(refused.size(), sweepColumns(unchecked).size());
  EXPECT_NE(refused.back().get<std::string>().find("expected a positive number"), std::string::npos) << refused.back();
}

TEST(SweepPool, StopsBetweenRowsWhenAsked) {
  const SweepSpec spec = example2Sweep();
  for (int jobs : {1, 2}) {
    std::vector<SweepRow> rows;
    runSweepPool(spec, 0, spec.runs(), jobs, [&rows](const SweepRow& r) { rows.push_back(r); },
                 [&rows] { return rows.size() >= 3; });
    ASSERT_EQ(rows.size(), 3u) << jobs << " jobs";
    for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i][0], i);
  }
}

}  // namespace
}  // namespace tabletop
