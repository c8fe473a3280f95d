// How a scenario's text reaches the loader and how its problems are
// placed: from a pipe or standard input, bounded like a file; on its real
// line whatever the line ends (LF, CR LF, a lone CR); with every value a
// message quotes cut to ScenarioLoader::kMaxQuotedBytes.

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "support/TempFiles.h"

namespace tabletop {
namespace {

const std::string kScene = R"({"version": 1, "name": "piped",
  "entities": [{"name": "A", "shape": "cube", "size": 0.1, "position": [0, 0], "mass": 1}]})";

// Writes `text` into a new pipe from a thread; `read` gets the read end.
// The writer ignores a reader that stops early (EPIPE, SIGPIPE ignored).
template <typename Read>
void throughPipe(const std::string& text, Read read) {
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  ::signal(SIGPIPE, SIG_IGN);
  std::thread writer([&text, fd = ends[1]] {
    for (std::size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
  });
  read(ends[0]);
  ::close(ends[0]);
  writer.join();
}

std::string problemOf(const std::string& path) {
  try {
    ScenarioLoader::loadFile(path);
  } catch (const ScenarioError& e) {
    return e.lines().front();
  }
  return "accepted";
}

TEST(ScenarioReading, ReadsAPipe) {
  throughPipe(kScene, [](int fd) {
    const Scenario s = ScenarioLoader::loadFile("/dev/fd/" + std::to_string(fd));
    EXPECT_EQ(s.name, "piped");
    EXPECT_EQ(s.entities.size(), 1u);
  });
}

TEST(ScenarioReading, ReadsStandardInputForADash) {
  throughPipe(kScene, [](int fd) {
    const int saved = ::dup(STDIN_FILENO);
    ::dup2(fd, STDIN_FILENO);
    std::string name, failure;
    try {
      const Scenario s = ScenarioLoader::loadFile("-");
      name = s.name + " from " + s.file;
    } catch (const ScenarioError& e) {
      failure = e.what();
    }
    ::dup2(saved, STDIN_FILENO);
    ::close(saved);
    EXPECT_EQ(name, "piped from <stdin>") << failure;
  });
}

// A pipe is bounded like a file: past kMaxFileBytes it is refused, having
// read no more than the bound and a chunk.
TEST(ScenarioReading, RefusesAPipeLongerThanAFile) {
  const std::string big = "[" + std::string(ScenarioLoader::kMaxFileBytes + 1000, ' ') + "]";
  throughPipe(big, [](int fd) {
    const std::string line = problemOf("/dev/fd/" + std::to_string(fd));
    EXPECT_NE(line.find("expected at most 16777216 bytes, got more"), std::string::npos) << line;
  });
}

// A named pipe that no one writes to reads as empty, at once.
TEST(ScenarioReading, ANamedPipeWithoutAWriterDoesNotWait) {
  const testing::TempFolder folder("scenario_fifo");
  const std::string fifo = folder.path() + "/scene.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string line = problemOf(fifo);
  EXPECT_NE(line.find("not valid JSON"), std::string::npos) << line;
}

TEST(ScenarioReading, RefusesDevicesAndDirectories) {
  for (const char* path : {"/", "/dev/zero", "/dev/null"}) {
    const std::string line = problemOf(path);
    EXPECT_NE(line.find("expected a regular file or a pipe"), std::string::npos) << path << ": " << line;
  }
}

// The same bad mass on line 4 with each convention of line ends, in
// white space and in a block comment.
TEST(ScenarioReading, PlacesProblemsOnTheirLineWhateverTheLineEnds) {
  for (const std::string end : {"\n", "\r\n", "\r"}) {
    const std::string text = "{\"version\": 1, \"name\": \"t\"," + end + "/* a" + end + "comment */ \"entities\": [" +
                             end + "{\"name\": \"A\", \"shape\": \"cube\", \"size\": 0.1, \"position\": [0, 0], \"mass\": -1}]}";
    try {
      ScenarioLoader::loadText(text, "ends.json");
      FAIL();
    } catch (const ScenarioError& e) {
      EXPECT_EQ(e.lines().front().rfind("ends.json:4:73:", 0), 0u) << e.lines().front();
    }
    // A syntax error, which the parser places by byte.
    try {
      ScenarioLoader::loadText("{\"version\": 1," + end + end + "  \"name\": }", "syntax.json");
      FAIL();
    } catch (const ScenarioError& e) {
      EXPECT_EQ(e.lines().front().rfind("syntax.json:3:11:", 0), 0u) << e.lines().front();
    }
  }
}

// A 1 MB number or string: the parser's message quotes it; the line
// shows kMaxQuotedBytes of it and how many bytes more there were.
TEST(ScenarioReading, CutsTheValuesTheParserQuotes) {
  for (const std::string& value : {std::string(1 << 20, '1'), "\"" + std::string(1 << 20, 'a') + "\\q\""}) {
    try {
      ScenarioLoader::loadText("{\"version\": 1, \"name\": \"t\",\n \"x\": " + value + "}", "big.json");
      FAIL();
    } catch (const ScenarioError& e) {
      const std::string line = e.lines().front();
      EXPECT_LT(line.size(), 300u) << line.substr(0, 300);
      EXPECT_NE(line.find("more bytes)"), std::string::npos) << line.substr(0, 300);
      EXPECT_EQ(line.rfind("big.json:2:", 0), 0u) << line.substr(0, 300);
    }
  }
}

}  // namespace
}  // namespace tabletop
