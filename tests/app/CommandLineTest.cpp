// The tabletop executable as a user runs it: output, errors, exit statuses.

#include <fcntl.h>
#include <sys/wait.h>

#include <csignal>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "core/ContactSolver.h"
#include "core/Settings.h"
#include "image/PngFile.h"
#include "support/CommandLine.h"

namespace {

using namespace tabletop::testing;

// The one run in run --json's document, {"format_version": 1, "runs": [...]}
// (the same shape for one scenario as for several).
nlohmann::json onlyRun(const std::string& text) {
  const nlohmann::json document = nlohmann::json::parse(text);
  EXPECT_EQ(document.at("format_version"), 1);
  EXPECT_EQ(document.at("runs").size(), 1u);
  return document.at("runs").at(0);
}

// The issue's check: the JSON object, with the struck cube dropped and the
// contact before the drop.
TEST(CommandLine, RunJsonPrintsTheOutcomeObject) {
  const Outcome o = run(kBin + "tabletop run " + kScenarios + "example2_two_cubes.json --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = onlyRun(o.out);
  for (const char* key : {"scenario", "mode", "settings", "sim_time", "steps", "wall_seconds", "entities",
                          "events", "state_hash"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["mode"], "bullet");
  EXPECT_EQ(j["state_hash"].get<std::string>().size(), 16u);
  const auto& b = j["entities"][1];
  EXPECT_EQ(b["name"], "B");
  EXPECT_EQ(b["orientation"].size(), 4u);
  EXPECT_EQ(b["position"].size(), 3u);
  const std::string status = b["status"];
  EXPECT_TRUE(status == "FinishDropSimulation" || status.rfind("DropFrom", 0) == 0) << status;
  int contact = -1, drop = -1;
  for (int i = 0; i < static_cast<int>(j["events"].size()); ++i) {
    const auto& e = j["events"][i];
    if (contact < 0 && e["type"] == "contact_begin") contact = i;
    if (drop < 0 && e["type"] == "leaves_table" && e["entities"][0] == "B") drop = i;
  }
  EXPECT_GE(contact, 0);
  EXPECT_GT(drop, contact);
}

// Overrides reach the run, and the text output lists entities and events.
TEST(CommandLine, RunTextHonoursOverrides) {
  const Outcome o = run(kBin + "tabletop run " + kScenarios +
                        "example1_single_cube.json --timestep 0.002 --iterations 20 --duration 0.5");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("timestep 0.002000 s, auto solver (dantzig where a load rests or anything but a ball slides with friction, else 20 iterations), trapezoid "
                        "integrator; simulated 0.500 s in 250 steps"), std::string::npos)
      << o.out;
  EXPECT_NE(o.out.find("push A Left"), std::string::npos);
  EXPECT_NE(o.out.find("state_hash"), std::string::npos);
}

// A scene on the Dantzig solver says so in its header, with the sweeps
// only islands over the row limit get.
TEST(CommandLine, RunHeaderNamesTheContactSolver) {
  const Outcome o = run(kBin + "tabletop run " + kScenarios + "hard/mass_ratio_100.json --duration 0.05");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find(", auto solver (dantzig where a load rests or anything but a ball slides with friction, else " +
                       std::to_string(tabletop::Settings{}.iterations) + " iterations), trapezoid integrator;"),
            std::string::npos)
      << o.out;
  // Two stacks, each an island carrying a load, over 3 steps: 6 solved
  // exactly, each by the guess of its pressing points, none swept.
  EXPECT_NE(o.out.find("islands solved exactly 6 (by the guess 6, by the pivoting 0), by sweeps 0, by sweeps after "
                       "the pivoting failed 0"),
            std::string::npos)
      << o.out;
}

// Two processes, the same scenario and settings: the same hash.
TEST(CommandLine, HashIsRepeatableAcrossProcesses) {
  const std::string cmd = kBin + "tabletop run " + kScenarios + "example3_stacked_cubes.json --json";
  const auto a = onlyRun(run(cmd).out);
  const auto b = onlyRun(run(cmd).out);
  EXPECT_EQ(a["state_hash"], b["state_hash"]);
}

// --threads and TABLETOP_THREADS share out the islands and change no bit;
// a count that is not a whole number from 1 to 256 is refused in one line
// naming both.
TEST(CommandLine, ThreadsChangeNoBitAndBadCountsAreRefused) {
  const std::string cmd = kBin + "tabletop run " + kScenarios + "example3_stacked_cubes.json --json";
  const auto one = onlyRun(run(cmd + " --threads 1").out);
  EXPECT_EQ(onlyRun(run(cmd + " --threads 4").out)["state_hash"], one["state_hash"]);
  EXPECT_EQ(onlyRun(run("env TABLETOP_THREADS=3 " + cmd).out)["state_hash"], one["state_hash"]);
  for (const std::string bad : {"--threads 0", "--threads 257", "--threads 2.5", "--threads x"}) {
    const Outcome o = run(cmd + " " + bad);
    EXPECT_EQ(o.status, 2) << bad;
    EXPECT_NE(o.err.find("expected a whole number from 1 to 256 (--threads or TABLETOP_THREADS)"), std::string::npos)
        << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
  }
  const Outcome o = run("env TABLETOP_THREADS=many " + cmd);
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("got 'many'"), std::string::npos) << o.err;
}

// Each report example is its own executable with the same options.
TEST(CommandLine, ExampleExecutablesRunTheirScenario) {
  const Outcome o = run(kBin + "tabletop-example4_two_spheres --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = onlyRun(o.out);
  EXPECT_EQ(j["scenario"], "example4_two_spheres");
  const auto file = onlyRun(run(kBin + "tabletop run --json " + kScenarios +
                                              "example4_two_spheres.json").out);
  EXPECT_EQ(j["state_hash"], file["state_hash"]);
}

TEST(CommandLine, HelpExplainsItself) {
  Outcome o = run(kBin + "tabletop --help");
  EXPECT_EQ(o.status, 0);
  EXPECT_NE(o.out.find("run"), std::string::npos);
  o = run(kBin + "tabletop run --help");
  EXPECT_EQ(o.status, 0);
  EXPECT_NE(o.out.find("--timestep"), std::string::npos);
}

// Bad input: one line per problem naming file and place, exit status 2,
// nothing on standard output.
TEST(CommandLine, BadScenarioIsOneLineAndStatusTwo) {
  const std::string path = writeTemp("bad_size.json", R"({"version": 1, "name": "t", "entities": [
    {"name": "A", "shape": "cube", "size": -0.1, "position": [0, 0], "mass": 1}]})");
  const Outcome o = run(kBin + "tabletop run " + path);
  EXPECT_EQ(o.status, 2);
  EXPECT_TRUE(o.out.empty()) << o.out;
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find(path + ":2:"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("at /entities/0/size: expected a positive number, got -0.1"), std::string::npos) << o.err;
}

TEST(CommandLine, NotJsonIsOneLineAndStatusTwo) {
  const std::string path = writeTemp("not_json.json", "{\n  \"version\": 1,\n  oops\n}");
  const Outcome o = run(kBin + "tabletop run " + path);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find(path + ":3:"), std::string::npos) << o.err;
}

TEST(CommandLine, OverlapAndMissingFileAndBadOptionsAreStatusTwo) {
  const std::string overlap = writeTemp("overlap.json", R"({"version": 1, "name": "t", "entities": [
    {"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1},
    {"name": "B", "shape": "cube", "size": 0.1, "position": [0.05, 0], "mass": 1}]})");
  Outcome o = run(kBin + "tabletop run " + overlap);
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("at /entities/1/position: expected 'B' clear of other bodies"), std::string::npos) << o.err;
  o = run(kBin + "tabletop run /no/such/scenario.json");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("cannot open"), std::string::npos) << o.err;
  o = run(kBin + "tabletop run " + kScenarios + "example1_single_cube.json --timestep -1");
  EXPECT_EQ(o.status, 2);
  o = run(kBin + "tabletop fly");
  EXPECT_EQ(o.status, 2);
  o = run(kBin + "tabletop");
  EXPECT_EQ(o.status, 2);
}

// A run that diverges: what it had on standard output marked incomplete,
// one line naming the entity, the time and the quantity, status 3.
TEST(CommandLine, DivergenceIsStatusThreeAndMarkedIncomplete) {
  const std::string path = writeTemp("absurd.json", R"({"version": 1, "name": "absurd",
    "settings": {"timestep": 0.1, "duration": 5},
    "entities": [{"name": "A", "shape": "cube", "size": 0.01, "position": [0, 0], "mass": 0.0001}],
    "script": [{"push": {"entity": "A", "direction": "Left", "impulse": 1e6}}]})");
  Outcome o = run(kBin + "tabletop run " + path);
  EXPECT_EQ(o.status, 3);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find(path + ": diverged at t = 0.1 s: entity 'A': position"), std::string::npos) << o.err;
  EXPECT_NE(o.out.find("INCOMPLETE"), std::string::npos) << o.out;
  o = run(kBin + "tabletop run --json " + path);
  EXPECT_EQ(o.status, 3);
  const nlohmann::json j = onlyRun(o.out);
  EXPECT_FALSE(j["complete"].get<bool>());
  EXPECT_NE(j["failure"].get<std::string>().find("entity 'A'"), std::string::npos);
  const std::string dir = ::tabletop::testing::tempDir() + "absurd_frames";
  std::filesystem::remove_all(dir);
  o = run(kBin + "tabletop render " + path + " --out-dir " + dir + " --at 0,0.5 --size 64x48");
  EXPECT_EQ(o.status, 3);
  EXPECT_NE(o.err.find("diverged at t = 0.1 s"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("the 1 frame before it in"), std::string::npos) << o.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/t_0.000.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/t_0.500.png"));
  // A finished run says it is complete.
  o = run(kBin + "tabletop run --json " + kScenarios + "example1_single_cube.json");
  EXPECT_EQ(o.status, 0);
  EXPECT_TRUE(onlyRun(o.out)["complete"].get<bool>());
}

// The command line's overrides are held to the same step budget.
TEST(CommandLine, OverridesThatAskForTooManyStepsAreStatusTwo) {
  const Outcome o = run(kBin + "tabletop run " + kScenarios + "example1_single_cube.json --timestep 1e-5 --duration 3000");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("expected at most 1e+07 steps"), std::string::npos) << o.err;
}

// Starts `tabletop ARGS...` in the background, its output in files.
// Renders example 2 at 400 frames per second (about 850 frames) and
// signals the render once five frames are there.
int interruptRender(const std::string& dir, int signal, std::string& err) {
  std::filesystem::remove_all(dir);
  const std::string errFile = dir + ".err";
  const pid_t pid = start({"render", kScenarios + "example2_two_cubes.json", "--out-dir", dir, "--fps", "400", "--size",
                           "160x120", "--video", dir + "/all.gif"},
                          errFile);
  for (int i = 0; i < 6000 && filesIn(dir, ".png").size() < 5; ++i) usleep(10000);
  kill(pid, signal);
  const int status = finish(pid);
  std::ifstream in(errFile);
  err.assign(std::istreambuf_iterator<char>(in), {});
  return status;
}

// Ctrl-C stops a long render cleanly: status 130, the frames made so far
// kept, each a whole PNG, no temporary file left and no video begun.
TEST(CommandLine, InterruptedRenderKeepsWholeFramesAndNoTemporaries) {
  const std::string dir = ::tabletop::testing::tempDir() + "interrupted_render";
  std::string err;
  EXPECT_EQ(interruptRender(dir, SIGINT, err), 130) << err;
  EXPECT_EQ(lineCount(err), 1) << err;
  EXPECT_NE(err.find("interrupted after"), std::string::npos) << err;
  EXPECT_NE(err.find("no video made"), std::string::npos) << err;
  const std::vector<std::string> frames = filesIn(dir, ".png");
  EXPECT_GE(frames.size(), 5u);
  EXPECT_LT(frames.size(), 800u);
  EXPECT_NE(err.find("after " + std::to_string(frames.size()) + " frames"), std::string::npos) << err;
  for (const std::string& f : frames) {
    const tabletop::Image image = tabletop::readPng(f);
    EXPECT_EQ(image.width, 160) << f;
    EXPECT_EQ(image.height, 120) << f;
  }
  EXPECT_TRUE(filesIn(dir, ".part").empty());
  EXPECT_FALSE(std::filesystem::exists(dir + "/all.gif"));
}

// A kill cannot be caught: it may leave a temporary file, but never a
// half-written frame under a frame's name, and the next render clears it.
TEST(CommandLine, KilledRenderLeavesNoHalfWrittenFrame) {
  const std::string dir = ::tabletop::testing::tempDir() + "killed_render";
  std::string err;
  EXPECT_EQ(interruptRender(dir, SIGKILL, err), kKilledBy + SIGKILL);
  const std::vector<std::string> frames = filesIn(dir, ".png");
  EXPECT_GE(frames.size(), 5u);
  for (const std::string& f : frames) EXPECT_NO_THROW(tabletop::readPng(f)) << f;
  const std::size_t left = filesIn(dir, ".part").size();
  EXPECT_LE(left, 1u);
  // The next render into the folder removes what the killed one left, and
  // says so.
  const Outcome o = runArgs({"render", kScenarios + "example1_single_cube.json", "--out-dir", dir, "--at", "0",
                             "--size", "64x48"});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err.find("removed 1 temporary file that a killed render left") != std::string::npos, left == 1)
      << o.err;
  EXPECT_TRUE(filesIn(dir, ".part").empty());
}

// run --out writes its output whole, or leaves the file as it was.
TEST(CommandLine, RunOutWritesTheFileWholeOrNotAtAll) {
  const std::string file = ::tabletop::testing::tempDir() + "run_out.json";
  std::filesystem::remove(file);
  Outcome o = run(kBin + "tabletop run --json --out " + file + " " + kScenarios + "example1_single_cube.json");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(o.out.empty()) << o.out;
  std::ifstream in(file);
  const nlohmann::json j = onlyRun(std::string(std::istreambuf_iterator<char>(in), {}));
  EXPECT_EQ(j["scenario"], "example1_single_cube");
  EXPECT_FALSE(std::filesystem::exists(file + ".part"));
  o = run(kBin + "tabletop run --out /no/such/dir/out.json " + kScenarios + "example1_single_cube.json");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
}

// run --trace writes a row per entity and step, from the initial state to
// the last step, and the last rows are the final state the run prints.
TEST(CommandLine, RunTraceWritesEveryStep) {
  const std::string file = ::tabletop::testing::tempDir() + "trace.csv";
  std::filesystem::remove(file);
  const std::string scene = kScenarios + "analytic/free_flight.json";
  Outcome o = run(kBin + "tabletop run --json --trace " + file + " " + scene);
  ASSERT_EQ(o.status, 0) << o.err;
  const nlohmann::json j = onlyRun(o.out);
  std::ifstream in(file);
  std::string line, last;
  std::getline(in, line);
  EXPECT_EQ(line, "t,step,entity,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    last = line;
  }
  EXPECT_EQ(rows, j["steps"].get<int>() + 1);  // one entity, the start and every step
  std::vector<double> fields;
  std::stringstream cells(last);
  std::string cell;
  while (std::getline(cells, cell, ',')) fields.push_back(cell == "A" ? 0.0 : std::stod(cell));
  ASSERT_EQ(fields.size(), 16u);
  const nlohmann::json& a = j["entities"][0];
  EXPECT_DOUBLE_EQ(fields[3], a["position"][0].get<double>());
  EXPECT_DOUBLE_EQ(fields[4], a["position"][1].get<double>());
  EXPECT_FALSE(std::filesystem::exists(file + ".part"));
  o = run(kBin + "tabletop run --trace " + file + " " + scene + " " + scene);
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
}

// bench sweeps the settings asked for: a table with the front marked, a
// CSV row per setting and a plot per scene; bad options are status 2.
TEST(CommandLine, BenchPrintsTheTableAndWritesCsvAndPlot) {
  const std::string dir = ::tabletop::testing::tempDir() + "bench_out";
  std::filesystem::remove_all(dir);
  Outcome o = run(kBin + "tabletop bench --scenarios " + kScenarios +
                  " --cases free_flight --repeats 1 --rates 60,240 --iterations 4,10 --out-dir " + dir);
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("free_flight  (error against the closed form)"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("*"), std::string::npos) << o.out;
  std::ifstream csv(dir + "/bench.csv");
  std::string line;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 1 + 2 * 2 * 2);  // rates x iterations x integrators
  EXPECT_TRUE(std::filesystem::exists(dir + "/bench_free_flight.png"));
  o = run(kBin + "tabletop bench --scenarios " + kScenarios + " --cases no_such_scene");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  o = run(kBin + "tabletop bench --rates 5");
  EXPECT_EQ(o.status, 2);
}

// run --tolerance says what it chose and why, and runs with it; with
// --json the choice goes to standard error and the settings into the JSON.
// A front file that cannot be read is one line and status 2.
TEST(CommandLine, RunToleranceChoosesAndSaysWhy) {
  const std::string front = " --front " + kData + "tolerance_front.json";
  Outcome o = run(kBin + "tabletop run " + kScenarios + "analytic/cube_slides_to_rest.json --tolerance 1e-3" + front);
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("cube_slides_to_rest: for an error of at most 0.001 m, chose "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("  sliding (cube_slides_to_rest): "), std::string::npos) << o.out;
  o = run(kBin + "tabletop run " + kScenarios + "analytic/cube_slides_to_rest.json --json --tolerance 1e-3" + front);
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find("for an error of at most 0.001 m"), std::string::npos) << o.err;
  const auto j = onlyRun(o.out);
  EXPECT_GT(j["settings"]["timestep"].get<double>(), 0.0);
  o = run(kBin + "tabletop run " + kScenarios + "analytic/cube_slides_to_rest.json --tolerance 1e-3 --front " +
          kScenarios + "no_such_front.json");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("no_such_front.json"), std::string::npos) << o.err;
}

// The modes are families of the sweep: compat and rules at the rates
// alone, and a scene they cannot run (a push by impulse) says so and is
// measured in bullet mode only.
TEST(CommandLine, BenchSweepsTheModes) {
  Outcome o = run(kBin + "tabletop bench --scenarios " + kScenarios +
                  " --cases straight_line_transfer --repeats 1 --rates 60,240 --iterations 4,10 --json");
  ASSERT_EQ(o.status, 0) << o.err;
  std::map<std::string, int> perMode;
  const nlohmann::json j = nlohmann::json::parse(o.out);
  for (const auto& p : j["sweep"]) ++perMode[p["mode"].get<std::string>()];
  EXPECT_EQ(perMode["bullet"], 2 * 2 * 2);
  EXPECT_EQ(perMode["compat"], 2);
  EXPECT_EQ(perMode["rules"], 2);
  o = run(kBin + "tabletop bench --scenarios " + kScenarios + " --cases free_flight --repeats 1 --rates 60 --iterations 4");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("(not in mode compat: "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("(not in mode rules: "), std::string::npos) << o.out;
}

// --switches and --scale are sections of their own: asked for alone they
// leave the sweep out; each switch is measured on every scene, and each
// size of the cube field with each switch, with a growth exponent.
TEST(CommandLine, BenchMeasuresTheModelSwitchesAndTheScale) {
  Outcome o = run(kBin + "tabletop bench --scenarios " + kScenarios +
                  " --cases free_flight --repeats 1 --switches --scale 4,9 --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = nlohmann::json::parse(o.out);
  EXPECT_TRUE(j["sweep"].empty());
  ASSERT_EQ(j["switches"].size(), 6u);
  EXPECT_EQ(j["switches"][0]["switch"], "defaults");
  for (const auto& p : j["switches"]) {
    EXPECT_EQ(p["scene"], "free_flight");
    EXPECT_GT(p["cost_ms_per_s"].get<double>(), 0.0);
  }
  ASSERT_EQ(j["scale"].size(), 2u * 6u);
  EXPECT_EQ(j["scale"][0]["cubes"], 4);
  EXPECT_TRUE(j["growth_exponents"].contains("defaults"));
  o = run(kBin + "tabletop bench --scenarios " + kScenarios + " --cases free_flight --repeats 1 --switches --scale 4,9");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("Model switches"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("growth exponent"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("(error against the closed form)"), std::string::npos) << o.out;
  o = run(kBin + "tabletop bench --scale 0");
  EXPECT_EQ(o.status, 2);
}

// --piles is a section of its own: each tiny pile runs its 2.5 s in
// tabletop and in Bullet, every column printed, the settled window
// measured for both, and a growth exponent for each engine.
TEST(CommandLine, BenchDropsPilesAgainstBullet) {
  Outcome o = run(kBin + "tabletop bench --piles 4,8 --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto j = nlohmann::json::parse(o.out);
  EXPECT_TRUE(j["sweep"].empty());
  ASSERT_EQ(j["piles"].size(), 2u);
  for (const char* key : {"bodies", "tabletop_ms_per_s", "bullet_ms_per_s", "ratio", "tabletop_drift_m",
                          "bullet_drift_m", "tabletop_penetration_m", "bullet_penetration_m",
                          "tabletop_energy_gain_j", "bullet_energy_gain_j", "simulated_s", "parts_per_step", "largest_island", "note"}) {
    EXPECT_TRUE(j["piles"][1].contains(key)) << key;
  }
  EXPECT_EQ(j["piles"][1]["bodies"], 8);
  EXPECT_DOUBLE_EQ(j["piles"][1]["simulated_s"].get<double>(), 2.5);
  // A step is one part at least; this small pile's steps stay within one
  // budget of kMaxParts (8) parts each.
  EXPECT_GE(j["piles"][1]["parts_per_step"].get<double>(), 1.0);
  EXPECT_LE(j["piles"][1]["parts_per_step"].get<double>(), 8.0);
  EXPECT_GE(j["piles"][1]["largest_island"].get<long>(), 1);
  EXPECT_LE(j["piles"][1]["largest_island"].get<long>(), 8);
  EXPECT_TRUE(j["piles"][1]["tabletop_drift_m"].is_number());
  EXPECT_TRUE(j["piles"][1]["bullet_drift_m"].is_number());
  EXPECT_TRUE(j["pile_exponents"].contains("tabletop"));
  EXPECT_TRUE(j["pile_exponents"].contains("bullet"));
  // Run again on 3 threads, the pile ends in the same state to the bit;
  // on one, there is no second run.
  o = run(kBin + "tabletop bench --piles 12 --threads 3 --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto threaded = nlohmann::json::parse(o.out)["piles"][0];
  EXPECT_EQ(threaded["threads"], 3);
  EXPECT_TRUE(threaded["threaded_ms_per_s"].is_number());
  EXPECT_EQ(threaded["threaded_same_state"], true);
  o = run("env TABLETOP_THREADS=1 " + kBin + "tabletop bench --piles 4 --json");
  ASSERT_EQ(o.status, 0) << o.err;
  const auto single = nlohmann::json::parse(o.out)["piles"][0];
  EXPECT_EQ(single["threads"], 1);
  EXPECT_TRUE(single["threaded_ms_per_s"].is_null());
  o = run(kBin + "tabletop bench --piles 4,8");
  ASSERT_EQ(o.status, 0) << o.err;
  for (const char* column : {"bodies", "tabletop [ms/s]", "Bullet [ms/s]", "ratio", "drift [mm]", "Bullet drift [mm]",
                             "deepest [mm]", "Bullet deepest [mm]", "gain [J]", "Bullet gain [J]", "simulated [s]",
                             "growth exponent"}) {
    EXPECT_NE(o.out.find(column), std::string::npos) << column << "\n" << o.out;
  }
  // A budget of a millisecond stops the first pile's tabletop run early
  // and leaves the second out, saying so.
  o = run(kBin + "tabletop bench --piles 4,8 --pile-budget 0.001");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("stopped at the 0.001 s budget"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("(left out after a pile stopped at the budget: 8 bodies)"), std::string::npos) << o.out;
  EXPECT_EQ(run(kBin + "tabletop bench --piles 0").status, 2);
}

// Every mode prints the same JSON keys for each entity.
TEST(CommandLine, EveryModeRunsWithTheSameOutputFormat) {
  std::vector<std::string> keys;
  for (const char* mode : {"bullet", "compat", "rules"}) {
    const Outcome o = run(kBin + "tabletop run --json --mode " + mode + " " + kScenarios + "example2_two_cubes.json");
    ASSERT_EQ(o.status, 0) << mode << ": " << o.err;
    const nlohmann::json j = onlyRun(o.out);
    EXPECT_EQ(j["mode"], mode);
    std::vector<std::string> these;
    for (const auto& [key, value] : j["entities"][0].items()) these.push_back(key);
    if (keys.empty()) keys = these;
    EXPECT_EQ(these, keys) << mode;
    EXPECT_EQ(j["entities"][1]["status"], "FinishDropSimulation") << mode;
  }
}

TEST(CommandLine, UnknownModeAndImpossiblePushesAreStatusTwo) {
  Outcome o = run(kBin + "tabletop run --mode physics " + kScenarios + "example1_single_cube.json");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("--mode"), std::string::npos) << o.err;
  EXPECT_TRUE(o.out.empty());
  const std::string grounded = writeTemp("grounded.json", R"({"version": 1, "name": "t", "entities": [
    {"name": "A", "shape": "cube", "size": 0.1, "position": [1.0, 0], "on": "ground", "mass": 1}],
    "script": [{"push": {"entity": "A", "direction": "Left", "step": 0.1}}]})");
  for (const char* mode : {"rules", "compat"}) {
    o = run(kBin + "tabletop run --mode " + std::string(mode) + " " + grounded);
    EXPECT_EQ(o.status, 2) << mode;
    EXPECT_EQ(lineCount(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("at /script/0: cannot do this action in mode " + std::string(mode) +
                         ": 'A' is on the ground"),
              std::string::npos)
        << o.err;
  }
  const std::string impulse = writeTemp("impulse.json", R"({"version": 1, "name": "t", "entities": [
    {"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}],
    "script": [{"push": {"entity": "A", "direction": "Left", "impulse": 0.5}}]})");
  o = run(kBin + "tabletop run --mode rules " + impulse);
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("give the push a 'step'"), std::string::npos) << o.err;
  o = run(kBin + "tabletop run --mode bullet " + impulse);
  EXPECT_EQ(o.status, 0) << o.err;
}

// The issue's check: compat and rules agree on misaligned_cubes.json,
// bullet diverges with a reason, and the plot is written whole.
TEST(CommandLine, CompareNamesWhereBulletDivergesAndPlotsIt) {
  const std::string plot = ::tabletop::testing::tempDir() + "tabletop_compare_" + std::to_string(getpid()) + ".png";
  std::remove(plot.c_str());
  Outcome o = run(kBin + "tabletop compare --json " + kScenarios + "misaligned_cubes.json --plot " + plot);
  ASSERT_EQ(o.status, 0) << o.err;
  const nlohmann::json j = nlohmann::json::parse(o.out);
  for (const auto& e : j["entities"]) {
    EXPECT_EQ(e["compat"]["verdict"], "agrees") << e["name"];
    EXPECT_LT(e["compat"]["distance_from_rules"].get<double>(), 1e-3);
    const std::string why = e["bullet"]["verdict"];
    EXPECT_EQ(why.rfind("diverges: stopped short, ", 0), 0u) << e["name"] << ": " << why;
    EXPECT_NE(why.find("rotated"), std::string::npos) << why;
  }
  std::ifstream png(plot, std::ios::binary);
  std::string magic(8, '\0');
  png.read(magic.data(), 8);
  EXPECT_EQ(magic, "\x89PNG\r\n\x1a\n");
  std::ifstream part(plot + ".part");
  EXPECT_FALSE(part.good()) << "temporary file left behind";
  std::remove(plot.c_str());

  o = run(kBin + "tabletop compare " + kScenarios + "misaligned_cubes.json");
  EXPECT_EQ(o.status, 0);
  EXPECT_NE(o.out.find("diverges: stopped short, "), std::string::npos) << o.out;
  o = run(kBin + "tabletop compare " + kScenarios + "misaligned_cubes.json --plot out.jpeg");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("expected a file name ending in .png or .svg"), std::string::npos) << o.err;
}

bool hasPartFiles(const std::string& dir) {
  for (const auto& f : std::filesystem::directory_iterator(dir)) {
    if (f.path().string().find(".part") != std::string::npos) return true;
  }
  return false;
}

// Stills at the times asked for, each a PNG of the size asked for.
TEST(CommandLine, RenderWritesStillsOfTheSizeAsked) {
  const TempFolder folder("render_stills", TempFolder::Start::Absent);
  const std::string& dir = folder.path();
  const Outcome o = run(kBin + "tabletop render " + kScenarios + "example2_two_cubes.json --out-dir " + dir +
                        " --at 1.6,0,0.5 --size 320x240 --camera corner --mode compat");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("3 frames of 320x240 (camera corner, mode compat)"), std::string::npos) << o.out;
  for (const char* name : {"t_0.000.png", "t_0.500.png", "t_1.600.png"}) {
    const tabletop::Image image = tabletop::readPng(dir + "/" + name);
    EXPECT_EQ(image.width, 320) << name;
    EXPECT_EQ(image.height, 240) << name;
  }
  EXPECT_FALSE(hasPartFiles(dir));
}

// Frames at --fps from 0 to the end of the run and half a second more,
// encoded into a GIF (frames kept with --keep-frames) and an MP4.
TEST(CommandLine, RenderMakesFramesAndVideos) {
  const TempFolder folder("render_video", TempFolder::Start::Absent);
  const std::string& dir = folder.path();
  Outcome o = run(kBin + "tabletop render " + kScenarios + "example2_two_cubes.json --out-dir " + dir +
                  " --fps 10 --size 160x120 --keep-frames --video " + dir + "/ex2.gif");
  ASSERT_EQ(o.status, 0) << o.err;
  // Frames every 0.1 s from 0 to where the run ends (everything at rest)
  // and half a second more.
  const double end =
      onlyRun(run(kBin + "tabletop run --json " + kScenarios + "example2_two_cubes.json").out)["sim_time"];
  const int last = static_cast<int>(std::floor((end + 0.5) * 10.0 + 1e-9));
  char name[32];
  std::snprintf(name, sizeof name, "/frame_%05d.png", last);
  EXPECT_TRUE(std::filesystem::exists(dir + name)) << name;
  std::snprintf(name, sizeof name, "/frame_%05d.png", last + 1);
  EXPECT_FALSE(std::filesystem::exists(dir + name)) << name;
  std::ifstream gif(dir + "/ex2.gif", std::ios::binary);
  std::string magic(6, '\0');
  gif.read(magic.data(), 6);
  EXPECT_EQ(magic, "GIF89a");

  // Without --keep-frames the frames go once the video is made.
  o = run(kBin + "tabletop render " + kScenarios + "example2_two_cubes.json --out-dir " + dir +
          " --fps 10 --size 161x121 --video " + dir + "/ex2.mp4");
  ASSERT_EQ(o.status, 0) << o.err;
  std::ifstream mp4(dir + "/ex2.mp4", std::ios::binary);
  std::string box(8, '\0');
  mp4.read(box.data(), 8);
  EXPECT_EQ(box.substr(4), "ftyp") << "not an MP4 file";
  EXPECT_TRUE(filesIn(dir, ".png").empty());
  EXPECT_FALSE(hasPartFiles(dir));
}

// A video alone needs no --out: the frames go to a private temporary
// folder that is gone afterwards; --keep-frames needs a folder to keep
// them in.
TEST(CommandLine, RenderMakesAVideoAloneAndLeavesNoFrames) {
  const TempFolder folder("render_video_alone", TempFolder::Start::Absent);
  const std::string& dir = folder.path();
  const std::string tmp = dir + "/tmp";
  std::filesystem::create_directories(tmp);
  const Outcome o = run("env TMPDIR=" + tmp + " " + kBin + "tabletop render " + kScenarios +
                        "example1_single_cube.json --fps 5 --size 80x60 --video " + dir + "/a.gif");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/a.gif"));
  EXPECT_TRUE(std::filesystem::is_empty(tmp)) << "the temporary frames are removed";
  EXPECT_EQ(o.out.find(" in "), std::string::npos) << o.out;
  const Outcome keep = run(kBin + "tabletop render " + kScenarios + "example1_single_cube.json --fps 5 --video " +
                           dir + "/b.gif --keep-frames");
  EXPECT_EQ(keep.status, 2);
  EXPECT_EQ(lineCount(keep.err), 1) << keep.err;
  EXPECT_NE(keep.err.find("--keep-frames: expected --out-dir DIR"), std::string::npos) << keep.err;
  const Outcome none = run(kBin + "tabletop render " + kScenarios + "example1_single_cube.json --fps 5");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("--out-dir: expected a folder for the frames"), std::string::npos) << none.err;
  const Outcome noFfmpeg = run("env PATH=/nonexistent " + kBin + "tabletop render " + kScenarios +
                               "example1_single_cube.json --fps 5 --video " + dir + "/c.gif");
  EXPECT_EQ(noFfmpeg.status, 1);
  EXPECT_EQ(lineCount(noFfmpeg.err), 1) << noFfmpeg.err;
  EXPECT_NE(noFfmpeg.err.find("ffmpeg is not installed"), std::string::npos) << noFfmpeg.err;
}

// Every --camera form renders; follow names an entity of the scene, and
// a wrong form or name is refused in one line before anything is made.
TEST(CommandLine, RenderTakesEveryCameraForm) {
  const TempFolder folder("render_cameras", TempFolder::Start::Absent);
  const std::string& dir = folder.path();
  for (const std::string camera : {"fit", "corner", "follow:B", "2,1.5,3:0,0.75,0"}) {
    const Outcome o = run(kBin + "tabletop render " + kScenarios + "example2_two_cubes.json --out-dir " + dir +
                          " --at 0 --size 80x60 --camera " + camera);
    EXPECT_EQ(o.status, 0) << camera << ": " << o.err;
    EXPECT_NE(o.out.find("(camera " + camera + ","), std::string::npos) << o.out;
  }
  std::filesystem::remove_all(dir);
  for (const std::string camera : {"follow:C", "ceiling", "1,2,3:1,2,3"}) {
    const Outcome o = run(kBin + "tabletop render " + kScenarios + "example2_two_cubes.json --out-dir " + dir +
                          " --at 0 --camera " + camera);
    EXPECT_EQ(o.status, 2) << camera;
    EXPECT_EQ(lineCount(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("--camera"), std::string::npos) << o.err;
    EXPECT_FALSE(std::filesystem::exists(dir)) << camera;
  }
}

// Without ffmpeg the frames are still made, and one line says why there is
// no video.
TEST(CommandLine, RenderWithoutFfmpegKeepsTheFrames) {
  const TempFolder folder("render_no_ffmpeg", TempFolder::Start::Absent);
  const std::string& dir = folder.path();
  const Outcome o = run("env PATH=/nonexistent " + kBin + "tabletop render " + kScenarios +
                        "example1_single_cube.json --out-dir " + dir + " --fps 5 --size 80x60 --video " + dir + "/a.mp4");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("ffmpeg is not installed"), std::string::npos) << o.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/frame_00000.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/a.mp4"));
}

// A run that takes more than half a second shows a bar with the time
// left on a terminal (here a pseudo-terminal made by script(1)), and
// nothing when standard error is not one.
TEST(CommandLine, LongWorkShowsProgressOnATerminalOnly) {
  const std::string command = kBin + "tabletop run " + kScenarios + "hard/pyramid_55.json --duration 2";
  const Outcome quiet = run(command);
  EXPECT_EQ(quiet.err, "");
  const Outcome terminal = run("script -qec '" + command + "' /dev/null");
  EXPECT_EQ(terminal.status, 0) << terminal.err;
  EXPECT_NE(terminal.out.find("\r["), std::string::npos) << terminal.out;
  EXPECT_NE(terminal.out.find(" left pyramid_55"), std::string::npos) << terminal.out;
  EXPECT_NE(terminal.out.find("\r\033[K"), std::string::npos) << "the bar is cleared";
  EXPECT_NE(terminal.out.find("pyramid_55"), std::string::npos) << terminal.out;
}

// --help speaks in words: values as NUMBER, INTEGER, TEXT or their
// choices with their ranges, none of CLI11's internal forms.
TEST(CommandLine, HelpIsPlainWords) {
  for (const std::string command : {"run", "compare", "view", "render", "bench"}) {
    const Outcome o = run(kBin + "tabletop " + command + " --help");
    EXPECT_EQ(o.status, 0) << command;
    for (const std::string raw : {"{false}", "{true}", "FLOAT", "INT:", "INT in", "ENUM", "TEXT:", "->"}) {
      EXPECT_EQ(o.out.find(raw), std::string::npos) << command << " shows '" << raw << "':\n" << o.out;
    }
  }
  const Outcome render = run(kBin + "tabletop render --help");
  EXPECT_NE(render.out.find("--timestep NUMBER from 1e-05 to 0.1"), std::string::npos) << render.out;
  EXPECT_NE(render.out.find("--iterations INTEGER from 1 to 10000"), std::string::npos) << render.out;
}

TEST(CommandLine, RenderRefusesBadOptionsInOneLine) {
  const TempFolder folder("render_bad", TempFolder::Start::Absent);
  const std::string& dir = folder.path();
  const std::string base = kBin + "tabletop render " + kScenarios + "example1_single_cube.json --out-dir " + dir;
  Outcome o = run(base + " --size 12by3");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
  EXPECT_NE(o.err.find("--size: expected WxH"), std::string::npos) << o.err;
  o = run(base + " --video out.avi");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("--video: expected a file name ending in .mp4 or .gif"), std::string::npos) << o.err;
  o = run(base + " --camera ceiling");
  EXPECT_EQ(o.status, 2);
  o = run(base + " --at 1 --fps 5");
  EXPECT_EQ(o.status, 2) << "--at and --fps exclude each other";
  EXPECT_FALSE(std::filesystem::exists(dir)) << "nothing is made for a refused command";
}

// No display: one line that says so and points to render, not a crash
// inside glutInit.
TEST(CommandLine, ViewWithoutADisplaySaysSoInOneLine) {
  for (const std::string env : {"env -u DISPLAY ", "env DISPLAY=:4242 "}) {
    const Outcome o = run(env + kBin + "tabletop view " + kScenarios + "example1_single_cube.json");
    EXPECT_EQ(o.status, 1) << env;
    EXPECT_EQ(lineCount(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("needs a display"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("tabletop render"), std::string::npos) << o.err;
  }
}

}  // namespace

namespace {

using namespace tabletop::testing;

// The program finds its own files from where it is, not from the current
// folder: --tolerance's front and bench's scenes, run from the root folder;
// --version names the build and where its files are.
TEST(CommandLine, RunsFromAnyFolderAndSaysItsVersion) {
  Outcome o = run("cd / && " + kBin + "tabletop run " + kScenarios + "example3_stacked_cubes.json --tolerance 1e-3");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("for an error of at most 0.001 m, chose"), std::string::npos) << o.out;
  o = run("cd / && " + kBin + "tabletop bench --cases free_flight --rates 60 --iterations 10 --repeats 1 --modes bullet");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("free_flight"), std::string::npos) << o.out;
  o = run(kBin + "tabletop --version");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out.rfind("tabletop 0.1.0 (Bullet ", 0), 0u) << o.out;
  EXPECT_NE(o.out.find(" precision)"), std::string::npos) << o.out;
  // Built, not installed: its files are the source tree's.
  EXPECT_NE(o.out.find(std::string("\ndata: ") + TABLETOP_SOURCE_DIR + "\n"), std::string::npos) << o.out;
}

}  // namespace

namespace {

using namespace tabletop::testing;

// Choices are names, in any case; a wrong one is refused in words, and help
// shows the names, not CLI11's mapping to numbers.
TEST(CommandLine, ChoicesAreNamesInAnyCase) {
  const std::string example = kScenarios + "example1_single_cube.json";
  Outcome o = run(kBin + "tabletop run " + example + " --mode RULES --integrator Euler");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("mode rules, timestep 0.004167 s, euler integrator"), std::string::npos) << o.out;
  o = run(kBin + "tabletop run " + example + " --mode nope");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.err.find("--mode: expected rules, compat or bullet, got 'nope'"), std::string::npos) << o.err;
  o = run(kBin + "tabletop run --help");
  EXPECT_NE(o.out.find("--mode rules|compat|bullet"), std::string::npos) << o.out;
  EXPECT_EQ(o.out.find("ENUM:"), std::string::npos) << o.out;
}

}  // namespace
