// tabletop sweep as a user runs it: bad specs refused with located lines,
// Ctrl-C keeping whole rows that a second sweep goes on from, the map.

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "support/CommandLine.h"

namespace tabletop::testing {
namespace {

// Example 2 over B's mass and the push's step, `count` steps, in the rules
// and in full physics.
std::string example2Spec(const std::string& name, int count) {
  return writeTemp(name, R"({"version": 1, "name": "cli", "scene": "example2_two_cubes",
    "parameters": [{"name": "mass", "pointer": "/entities/1/mass", "values": [0.5, 1.0]},
                   {"name": "step", "pointer": "/script/0/push/step", "range": {"from": 0.6, "to": 1.0, "count": )" +
                               std::to_string(count) + R"(}}],
    "modes": ["rules", "bullet"]})");
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<nlohmann::json> jsonLines(const std::string& path) {
  std::ifstream in(path);
  std::vector<nlohmann::json> rows;
  for (std::string line; std::getline(in, line);) {
    nlohmann::json row = nlohmann::json::parse(line);
    for (auto it = row.begin(); it != row.end();) it = it.key().find("wall_s") != std::string::npos ? row.erase(it) : ++it;
    rows.push_back(row);
  }
  return rows;
}

TEST(SweepCommand, RefusesABadSpecWithOneLocatedLine) {
  const std::string spec = writeTemp("sweep_bad.json", "{\"version\": 1, \"name\": \"x\", \"scene\": \"example2_two_cubes\",\n"
                                                       " \"parameters\": [{\"pointer\": \"/entities/1/mass\", \"values\": [1, 0]}],\n"
                                                       " \"modes\": [\"rules\"]}");
  const Outcome o = runArgs({"sweep", spec});
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find(spec + ":2:17: at /parameters/0: run 1 (/entities/1/mass = 0)"), std::string::npos) << o.err;
  EXPECT_EQ(runArgs({"sweep", spec, "--plot", "map.txt"}).status, 2);
  EXPECT_EQ(runArgs({"sweep", spec, "--jobs", "0"}).status, 2);
  EXPECT_EQ(runArgs({"sweep", "/dev/zero"}).status, 2);
}

// --random N: the random stability runs from --seed on, a row each, the
// summary saying how many are stable; the options that make no sense
// together refused.
TEST(SweepCommand, RandomRunsAreCheckedAndSummed) {
  TempFolder folder("sweep_random");
  const std::string prefix = folder.path() + "/r";
  const Outcome o = runArgs({"sweep", "--random", "4", "--seed", "7", "--rate", "60", "--jobs", "2", "--out", prefix});
  EXPECT_EQ(o.status, 0) << o.err;
  const std::vector<nlohmann::json> rows = jsonLines(prefix + ".jsonl");
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]["seed"], 7 + i);
    EXPECT_EQ(rows[i]["bullet.stable"], true);
  }
  // With no table the summary goes to the errors' stream, after the rows.
  const Outcome summed = runArgs({"sweep", "--random", "2", "--seed", "7", "--rate", "60", "--jobs", "1"});
  EXPECT_EQ(summed.status, 0) << summed.err;
  EXPECT_NE(summed.err.find("random: 2 runs; all stable"), std::string::npos) << summed.err;
  EXPECT_EQ(runArgs({"sweep", "--seed", "7"}).status, 2);
  EXPECT_EQ(runArgs({"sweep", "--random", "0"}).status, 2);
  EXPECT_EQ(runArgs({"sweep", "--random", "2", "--rate", "nan"}).status, 2);
  EXPECT_EQ(runArgs({"sweep", "--random", "2", "--rate", "1e9"}).status, 2);
  EXPECT_EQ(runArgs({"sweep", example2Spec("sweep_both.json", 2), "--random", "2"}).status, 2);
}

TEST(SweepCommand, CtrlCKeepsWholeRowsAndTheSameCommandGoesOn) {
  TempFolder folder("sweep_interrupt");
  const std::string spec = example2Spec("sweep_interrupt.json", 40);
  const std::string stopped = folder.path() + "/stopped", whole = folder.path() + "/whole";
  const std::string errFile = folder.path() + "/err.txt";
  const pid_t pid = start({"sweep", spec, "--out", stopped, "--jobs", "2"}, errFile);
  // Interrupted once three rows are in.
  for (int k = 0; k < 6000 && lineCount(readFile(stopped + ".jsonl")) < 3; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGINT);
  ASSERT_EQ(finish(pid), 130) << readFile(errFile);
  EXPECT_NE(readFile(errFile).find("interrupted after"), std::string::npos) << readFile(errFile);
  const std::size_t kept = jsonLines(stopped + ".jsonl").size();
  EXPECT_GE(kept, 3u);
  EXPECT_LT(kept, 80u);
  EXPECT_EQ(lineCount(readFile(stopped + ".csv")), static_cast<int>(kept) + 1);
  // The same command finishes it; the table is the one an unbroken sweep writes.
  const Outcome resumed = runArgs({"sweep", spec, "--out", stopped});
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  ASSERT_EQ(runArgs({"sweep", spec, "--out", whole, "--jobs", "1"}).status, 0);
  const std::vector<nlohmann::json> a = jsonLines(stopped + ".jsonl"), b = jsonLines(whole + ".jsonl");
  ASSERT_EQ(a.size(), 80u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(lineCount(readFile(stopped + ".csv")), 81);
}

TEST(SweepCommand, PlotsTheMapOfTwoParameters) {
  TempFolder folder("sweep_plot");
  const std::string spec = example2Spec("sweep_plot.json", 3);
  const std::string map = folder.path() + "/map.png";
  const Outcome o = runArgs({"sweep", spec, "--out", folder.path() + "/t", "--plot", map});
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(readFile(map).substr(0, 8), "\x89PNG\r\n\x1a\n");
  // One parameter is no map: the table is written, the plot refused.
  const std::string one = writeTemp("sweep_one.json", R"({"version": 1, "name": "one", "scene": "example2_two_cubes",
    "parameters": [{"pointer": "/entities/1/mass", "values": [0.5]}], "modes": ["rules", "bullet"]})");
  const Outcome refused = runArgs({"sweep", one, "--out", folder.path() + "/one", "--plot", folder.path() + "/one.png"});
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("the map needs two varied parameters"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(folder.path() + "/one.png"));
}

}  // namespace
}  // namespace tabletop::testing
