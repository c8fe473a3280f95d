// Input from someone else, given to the tabletop executable: no text may
// become a command, no output may replace what is not a regular file, no
// number may be NaN, and Ctrl-C leaves nothing half written.

#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/CommandLine.h"

namespace {

using namespace tabletop::testing;

// A one-cube scenario named `name` whose entity is named `entity` (both
// JSON string bodies, escapes allowed), pushed off the right edge.
std::string scene(const std::string& name, const std::string& entity) {
  return R"({"version": 1, "name": ")" + name + R"(", "entities": [{"name": ")" + entity +
         R"(", "shape": "cube", "size": 0.1, "position": [0.3, 0], "mass": 1}],
  "script": [{"push": {"entity": ")" + entity + R"(", "direction": "Left", "step": 0.5}}]})";
}

// Quotes and backquotes are printable, so such names are accepted; gnuplot
// gets them in single quotes, where it substitutes nothing: the commands
// they spell never run, and the plot is made.
TEST(HostileInput, NamesNeverRunAsGnuplotCommands) {
  const TempFolder folder("hostile_plot");
  const std::string& dir = folder.path();
  // The marker's path is written into an entity name, at most 64 bytes: a
  // folder in the system's temporary folder, as one in the build tree may
  // be too long.
  const TempFolder markerDir("tabletop", TempFolder::Start::Empty,
                             std::filesystem::temp_directory_path().string() + "/");
  const std::string marker = markerDir.path() + "/ran";
  const std::string file = writeTemp("hostile_plot.json",
                                     scene("t' `touch " + marker + "` '", "A'\\n`touch " + marker + "`"));
  // The newline escape makes the entity name refused; the scenario name alone
  // is then the hostile one.
  Outcome o = runArgs({"compare", file, "--plot", dir + "/p.png"});
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find("expected printable text"), std::string::npos) << o.err;
  const std::string ok = writeTemp("hostile_plot2.json", scene("t' `touch " + marker + "` '", "A'`touch " + marker + "`"));
  o = runArgs({"compare", ok, "--plot", dir + "/p.png"});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/p.png"));
  EXPECT_FALSE(std::filesystem::exists(marker));
  EXPECT_TRUE(filesIn(dir, ".part").empty());
}

// A name with a comma and a quote is one field of the trace (RFC 4180).
TEST(HostileInput, TraceQuotesNamesAsCsvFields) {
  const TempFolder folder("hostile_trace");
  const std::string& dir = folder.path();
  const std::string file = writeTemp("hostile_trace.json", scene("t", R"(A, \"b\")"));
  const Outcome o = runArgs({"run", file, "--trace", dir + "/t.csv", "--duration", "0.05"});
  ASSERT_EQ(o.status, 0) << o.err;
  std::ifstream in(dir + "/t.csv");
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(row.rfind("0,0,\"A, \"\"b\"\"\",", 0), 0u) << row;
  // Sixteen fields: the quoted one holds one comma.
  EXPECT_EQ(std::count(row.begin(), row.end(), ','), 16) << row;
}

// Outputs replace regular files only: a link to a device or a directory is
// refused before the run, and the device stays a device.
TEST(HostileInput, WritesOnlyReplaceRegularFiles) {
  const TempFolder folder("hostile_devices");
  const std::string& dir = folder.path();
  const std::string link = dir + "/null.json";
  std::filesystem::create_symlink("/dev/null", link);
  const std::string example = kScenarios + "example1_single_cube.json";
  for (const std::string& out : {link, dir, std::string("/dev/null")}) {
    const Outcome o = runArgs({"run", example, "--out", out});
    EXPECT_EQ(o.status, 1) << out << ": " << o.err;
    EXPECT_EQ(lineCount(o.err), 1) << o.err;
  }
  struct stat info {};
  ASSERT_EQ(stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  // A link to a regular file is written through: the link stays a link.
  const std::string target = dir + "/target.txt", second = dir + "/link.txt";
  std::ofstream(target) << "old";
  std::filesystem::create_symlink(target, second);
  const Outcome o = runArgs({"run", example, "--out", second});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_TRUE(std::filesystem::is_symlink(second));
  EXPECT_GT(std::filesystem::file_size(target), 100u);
  EXPECT_TRUE(filesIn(dir, ".part").empty());
}

// NaN and infinity are command-line errors (status 2) for every number.
TEST(HostileInput, NumbersOnTheCommandLineMustBeFinite) {
  const std::string example = kScenarios + "example1_single_cube.json";
  const std::vector<std::vector<std::string>> calls{
      {"run", example, "--tolerance", "nan"},         {"run", example, "--timestep", "nan"},
      {"run", example, "--duration", "inf"},          {"run", example, "--timestep", "-inf"},
      {"render", example, "--out-dir", "x", "--fps", "nan"}, {"render", example, "--out-dir", "x", "--at", "nan"},
      {"render", example, "--out-dir", "x", "--at", "1e300"}, {"bench", "--rates", "nan"}};
  for (const auto& args : calls) {
    const Outcome o = runArgs(args);
    EXPECT_EQ(o.status, 2) << args[0] << " " << args.back() << ": " << o.err;
    EXPECT_NE(o.err.find("expected a"), std::string::npos) << o.err;
  }
  EXPECT_FALSE(std::filesystem::exists("x"));
}

// Ctrl-C during a long run with --trace: status 130, no trace, no
// temporary left beside it.
TEST(HostileInput, InterruptedRunLeavesNoTemporary) {
  const TempFolder folder("hostile_interrupt");
  const std::string& dir = folder.path();
  const std::string file = writeTemp("hostile_long.json", R"({"version": 1, "name": "long",
    "settings": {"timestep": 1e-3, "duration": 3000, "end_at_rest": false},
    "entities": [{"name": "A", "shape": "sphere", "size": 0.05, "position": [0, 2, 0], "mass": 1}]})");
  const pid_t pid = start({"run", file, "--trace", dir + "/t.csv"}, dir + "/err.txt");
  // Wait until the temporary trace is there, then interrupt.
  for (int i = 0; i < 3000; ++i) {
    if (!filesIn(dir, ".part").empty()) break;
    usleep(10000);
  }
  usleep(100000);
  kill(pid, SIGINT);
  EXPECT_EQ(finish(pid), 130);
  std::ifstream in(dir + "/err.txt");
  const std::string err((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(err.find("interrupted"), std::string::npos) << err;
  EXPECT_TRUE(filesIn(dir, ".part").empty());
  EXPECT_FALSE(std::filesystem::exists(dir + "/t.csv"));
}

// A trace larger than its cap is not written, and the run says why.
TEST(HostileInput, TraceStaysUnderItsCap) {
  const TempFolder folder("hostile_cap");
  const std::string& dir = folder.path();
  const Outcome o = runArgs({"run", kScenarios + "example2_two_cubes.json", "--trace", dir + "/t.csv",
                             "--trace-max-mb", "0.01"});
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_NE(o.err.find("larger than 0.01 MB"), std::string::npos) << o.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/t.csv"));
  EXPECT_TRUE(filesIn(dir, ".part").empty());
}

// A --duration that ends before the script's last action says so, at the
// action's place in the file.
TEST(HostileInput, DurationShorterThanTheScriptIsWarned) {
  const std::string file = writeTemp("hostile_short.json", R"({"version": 1, "name": "t",
    "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}],
    "script": [{"t": 2, "push": {"entity": "A", "direction": "Left", "step": 0.1}}]})");
  const Outcome o = runArgs({"run", file, "--duration", "1"});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.err.find(file + ":3:22: at /script/0/t: warning: the duration"), std::string::npos) << o.err;
}

// A scenario from standard input ("-") or a pipe runs as from its file
// (the same state hash), named <stdin> or by the pipe's path; a device is
// still refused.
TEST(HostileInput, AScenarioFromAPipeOrStandardInput) {
  const std::string file = kScenarios + "example2_two_cubes.json";
  const std::string bin = kBin + "tabletop";
  const Outcome fromFile = run("'" + bin + "' run --json '" + file + "'");
  ASSERT_EQ(fromFile.status, 0) << fromFile.err;
  const auto hash = [](const std::string& out) {
    const std::size_t at = out.find("\"state_hash\"");
    return at == std::string::npos ? std::string() : out.substr(at, 40);
  };
  const Outcome fromStdin = run("'" + bin + "' run --json - < '" + file + "'");
  EXPECT_EQ(fromStdin.status, 0) << fromStdin.err;
  EXPECT_NE(fromStdin.out.find("\"file\": \"<stdin>\""), std::string::npos) << fromStdin.out.substr(0, 300);
  const Outcome fromPipe = run("bash -c \"'" + bin + "' run --json <(cat '" + file + "')\"");
  EXPECT_EQ(fromPipe.status, 0) << fromPipe.err;
  EXPECT_FALSE(hash(fromFile.out).empty());
  EXPECT_EQ(hash(fromStdin.out), hash(fromFile.out));
  EXPECT_EQ(hash(fromPipe.out), hash(fromFile.out));
  const Outcome device = runArgs({"run", "/dev/zero"});
  EXPECT_EQ(device.status, 2);
  EXPECT_NE(device.err.find("expected a regular file or a pipe"), std::string::npos) << device.err;
}

// The plot's name is checked before anything runs.
TEST(HostileInput, PlotNameIsCheckedFirst) {
  const Outcome o = runArgs({"compare", kScenarios + "hard/pyramid_55.json", "--plot", "p.jpeg"});
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(lineCount(o.err), 1) << o.err;
}

}  // namespace

namespace {

using namespace tabletop::testing;

// A load far heavier than what it stands on (1e9 times) pushes it through
// the table top: the run says so and stops (status 3), rather than report
// the light cube OnTable inside the top.
TEST(HostileInput, ABodyPassingThroughTheTableTopIsADivergence) {
  // By few sweeps: the exact solver holds even this load (1e9 : 1) up, and
  // at 8 to 10 sweeps the light cube is squeezed out sideways instead (1 to
  // 6 all pass it through).
  const std::string file = writeTemp("hostile_heavy.json", R"({"version": 1, "name": "heavy",
    "settings": {"solver": "sequential_impulse", "iterations": 4}, "entities": [
    {"name": "L", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1e-4},
    {"name": "H", "shape": "cube", "size": 0.1, "position": [0, 0], "on": "L", "mass": 1e5}]})");
  const Outcome o = runArgs({"run", file});
  EXPECT_EQ(o.status, 3) << o.err;
  EXPECT_NE(o.err.find("entity 'L': centre at y = "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("is inside the table top"), std::string::npos) << o.err;
}

}  // namespace

namespace {

using namespace tabletop::testing;

// With no gravity a push by step would give no impulse: refused at the
// push's place, in full physics; the rules move it by the step all the same.
TEST(HostileInput, AStepPushWithoutGravityIsRefusedAtItsPlace) {
  const std::string file = writeTemp("hostile_nogravity.json", R"({"version": 1, "name": "t",
    "settings": {"gravity": 0},
    "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}],
    "script": [{"push": {"entity": "A", "direction": "Left", "step": 0.1}}]})");
  Outcome o = runArgs({"run", file});
  EXPECT_EQ(o.status, 2) << o.err;
  EXPECT_NE(o.err.find(file + ":4:16: at /script/0: cannot do this action in mode bullet: with no gravity"),
            std::string::npos)
      << o.err;
  o = runArgs({"run", file, "--mode", "rules"});
  EXPECT_EQ(o.status, 0) << o.err;
}

}  // namespace

namespace {

using namespace tabletop::testing;

// Refusals found when the scene is built, not when it is read, are located
// in the file as the loader's are: an overlap, a starting velocity the
// rules cannot have.
TEST(HostileInput, RefusalsAtBuildTimeAreLocated) {
  const std::string file = writeTemp("hostile_overlap.json", R"({"version": 1, "name": "ov", "entities": [
 {"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1},
 {"name": "B", "shape": "cube", "size": 0.1, "position": [0.05, 0], "mass": 1, "velocity": [1, 0, 0]}]})");
  Outcome o = runArgs({"run", file});
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, file + ":3:58: at /entities/1/position: expected 'B' clear of other bodies at the start, "
                          "but it overlaps 'A'\n");
  o = runArgs({"run", file, "--mode", "rules"});
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err.rfind(file + ":3:92: at /entities/1/velocity: expected no starting velocity", 0), 0u) << o.err;
}

}  // namespace
