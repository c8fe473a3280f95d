// Every output written whole or not at all, on every path: a plot on a
// full disk (a file size limit in the child, as a small file system is not
// to be had), output names that are not printable, --out and --trace
// naming one file however spelt, and a render's private frame folder
// after a kill -9.

#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/CommandLine.h"

namespace {

using namespace tabletop::testing;

std::string contentOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Starts tabletop with `args` as start() does, with files limited to
// `maxFileBytes` (0: no limit; tabletop ignores SIGXFSZ, so writes past it
// fail as on a full disk) and TMPDIR set to `tmp`.
pid_t startLimited(const std::vector<std::string>& args, const std::string& errFile, rlim_t maxFileBytes,
                   const std::string& tmp = "") {
  return start(args, errFile, [&] {
    if (maxFileBytes > 0) {
      const rlimit limit{maxFileBytes, maxFileBytes};
      setrlimit(RLIMIT_FSIZE, &limit);
    }
    if (!tmp.empty()) setenv("TMPDIR", tmp.c_str(), 1);
  });
}

// gnuplot exits 0 when its writes fail; the plot is checked whole, and the
// previous one stays: status 1 with the reason, nothing else left.
TEST(OutputsWhole, APlotOnAFullDiskKeepsThePreviousOne) {
  // Room for gnuplot's script (on its standard input, through a temporary
  // file), not for the plot.
  constexpr rlim_t kLimit = 16384;
  const TempFolder folder("whole_plot");
  const std::string& dir = folder.path();
  for (const std::string name : {"p.png", "p.svg"}) {
    const std::string plot = dir + "/" + name;
    std::ofstream(plot) << "previous";
    const pid_t pid = startLimited({"compare", kScenarios + "misaligned_cubes.json", "--plot", plot},
                                   dir + "/err.txt", kLimit);
    EXPECT_EQ(finish(pid), 1) << name;
    const std::string err = contentOf(dir + "/err.txt");
    EXPECT_NE(err.find("gnuplot failed to write"), std::string::npos) << err;
    EXPECT_NE(err.find("incomplete"), std::string::npos) << err;
    EXPECT_EQ(contentOf(plot), "previous");
    EXPECT_TRUE(filesIn(dir, ".part").empty());
    EXPECT_TRUE(filesIn(dir, ".log").empty());
  }
  // Without the limit the same plot is made whole.
  const Outcome o = runArgs({"compare", kScenarios + "misaligned_cubes.json", "--plot", dir + "/p.png"});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_GT(std::filesystem::file_size(dir + "/p.png"), kLimit);
}

// An output name with a control character (a newline could start a
// gnuplot command, and shows as two lines) or a direction mark is refused
// before anything runs, and nothing is written.
TEST(OutputsWhole, OutputNamesMustBePrintable) {
  const TempFolder folder("whole_names");
  const std::string& dir = folder.path();
  const std::string example = kScenarios + "example1_single_cube.json";
  for (const std::string bad : {"a\nb", "a\x1b[31mb", "a\xe2\x80\xae" "b"}) {
    Outcome o = runArgs({"compare", example, "--plot", dir + "/" + bad + ".png"});
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_EQ(lineCount(o.err), 1) << o.err;
    EXPECT_NE(o.err.find("expected a printable file name"), std::string::npos) << o.err;
    o = runArgs({"run", example, "--out", dir + "/" + bad + ".txt"});
    EXPECT_EQ(o.status, 1) << o.err;
    EXPECT_NE(o.err.find("expected a printable file name"), std::string::npos) << o.err;
    o = runArgs({"render", example, "--video", dir + "/" + bad + ".gif"});
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("expected a printable file name"), std::string::npos) << o.err;
    o = runArgs({"render", example, "--out-dir", dir + "/" + bad, "--at", "0"});
    EXPECT_EQ(o.status, 2) << o.err;
    EXPECT_NE(o.err.find("expected a printable folder name"), std::string::npos) << o.err;
    EXPECT_EQ(lineCount(o.err), 1) << o.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// --out and --trace into one file would leave only one of them: refused
// however the second is spelt, and the file is left as it was.
TEST(OutputsWhole, OutAndTraceCannotNameOneFile) {
  const TempFolder folder("whole_same");
  const std::string& dir = folder.path();
  const std::string example = kScenarios + "example1_single_cube.json";
  std::filesystem::create_directories(dir + "/sub");
  const std::string file = dir + "/f.txt";
  // A file not made yet, by two spellings of its path.
  for (const std::string& other : std::vector<std::string>{file, dir + "/./f.txt", dir + "/sub/../f.txt"}) {
    const Outcome o = runArgs({"run", example, "--out", file, "--trace", other});
    EXPECT_EQ(o.status, 2) << other << ": " << o.err;
    EXPECT_NE(o.err.find("name the same file"), std::string::npos) << o.err;
    EXPECT_FALSE(std::filesystem::exists(file));
  }
  // An existing file, and a link and a hard link to it.
  std::ofstream(file) << "old";
  std::filesystem::create_symlink(file, dir + "/link.txt");
  std::filesystem::create_hard_link(file, dir + "/hard.txt");
  for (const std::string& other : std::vector<std::string>{dir + "/link.txt", dir + "/hard.txt"}) {
    const Outcome o = runArgs({"run", example, "--out", file, "--trace", other});
    EXPECT_EQ(o.status, 2) << other << ": " << o.err;
    EXPECT_EQ(contentOf(file), "old");
  }
  const Outcome o = runArgs({"run", example, "--out", file, "--trace", dir + "/t.csv"});
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_NE(contentOf(file), "old");
  EXPECT_GT(std::filesystem::file_size(dir + "/t.csv"), 100u);
}

// A render killed with kill -9 cannot remove its private frame folder; the
// next render finds it (no living render holds it), removes it and names
// it. A living render's folder is left alone.
TEST(OutputsWhole, TheNextRenderRemovesAKilledRendersFrames) {
  const TempFolder folder("whole_render");
  const std::string& dir = folder.path();
  const TempFolder tmp("whole_render_tmp");
  const auto scratch = [&] {
    std::vector<std::string> found;
    for (const auto& e : std::filesystem::directory_iterator(tmp.path())) {
      if (e.path().filename().string().rfind("tabletop-frames-", 0) == 0) found.push_back(e.path().string());
    }
    return found;
  };
  const std::string example = kScenarios + "example2_two_cubes.json";
  const pid_t killed = startLimited({"render", example, "--video", dir + "/v.gif", "--size", "64x48", "--fps", "1000"},
                                    dir + "/err1.txt", 0, tmp.path());
  std::vector<std::string> left;
  for (int i = 0; i < 3000 && left.empty(); ++i) {
    const auto found = scratch();
    if (!found.empty() && !filesIn(found.front(), ".png").empty()) left = found;
    usleep(10000);
  }
  ASSERT_EQ(left.size(), 1u) << contentOf(dir + "/err1.txt");
  kill(killed, SIGKILL);
  EXPECT_EQ(finish(killed), kKilledBy + SIGKILL);
  ASSERT_TRUE(std::filesystem::is_directory(left.front()));

  const pid_t next = startLimited({"render", example, "--video", dir + "/w.gif", "--size", "32x24", "--fps", "2"},
                                  dir + "/err2.txt", 0, tmp.path());
  EXPECT_EQ(finish(next), 0) << contentOf(dir + "/err2.txt");
  const std::string err = contentOf(dir + "/err2.txt");
  EXPECT_NE(err.find("removed " + left.front() + ", the frames of a killed render"), std::string::npos) << err;
  EXPECT_TRUE(scratch().empty());
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/w.gif"));
}

// SIGTERM while ffmpeg encodes (tabletop alone gets it, not ffmpeg) ends
// the render with 130, ffmpeg ended, and the video left as it was: the
// last whole one, as Ctrl-C leaves every whole frame.
TEST(OutputsWhole, SigtermWhileEncodingKeepsThePreviousVideo) {
  const TempFolder folder("whole_encode");
  const std::string& dir = folder.path();
  const TempFolder tmp("whole_encode_tmp");
  const std::string video = dir + "/v.gif";
  std::ofstream(video) << "previous";
  const pid_t pid = startLimited({"render", kScenarios + "example2_two_cubes.json", "--video", video, "--size",
                                  "240x180", "--fps", "200"},
                                 dir + "/err.txt", 0, tmp.path());
  // The video's temporary appears when the encoding starts.
  bool encoding = false;
  for (int i = 0; i < 6000 && !encoding; ++i) {
    for (const std::string& part : filesIn(dir, ".part")) encoding = encoding || part.find("v.gif.") != std::string::npos;
    usleep(10000);
  }
  ASSERT_TRUE(encoding) << contentOf(dir + "/err.txt");
  kill(pid, SIGTERM);
  EXPECT_EQ(finish(pid), 130);
  const std::string err = contentOf(dir + "/err.txt");
  EXPECT_NE(err.find("interrupted while encoding; " + video + " left as it was"), std::string::npos) << err;
  EXPECT_EQ(contentOf(video), "previous");
  EXPECT_TRUE(filesIn(dir, ".part").empty());
  EXPECT_TRUE(filesIn(dir, ".log").empty());
  EXPECT_TRUE(std::filesystem::is_empty(tmp.path()));
}

}  // namespace
