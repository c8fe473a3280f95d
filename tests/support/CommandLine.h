#pragma once

// Runs the built tabletop executables as a user would, for the tests of
// tests/app: the command, its output, its error stream and its status.

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/TempFiles.h"

namespace tabletop::testing {

struct Outcome {
  int status = -1;
  std::string out;
  std::string err;
};

inline const std::string kBin = std::string(TABLETOP_BINARY_DIR) + "/src/app/";
inline const std::string kScenarios = std::string(TABLETOP_SOURCE_DIR) + "/scenarios/";
inline const std::string kData = std::string(TABLETOP_SOURCE_DIR) + "/data/";

// The text of `file`, which is then removed (a test's error file).
inline std::string readAndRemove(const std::string& file) {
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::error_code ignored;
  std::filesystem::remove(file, ignored);
  return text;
}

// Runs a shell command, capturing stdout, and stderr through a file.
inline Outcome run(const std::string& command) {
  // One file per test process: CTest runs tests in parallel.
  const std::string errFile = ::tabletop::testing::tempDir() + "tabletop_stderr_" + std::to_string(getpid()) + ".txt";
  Outcome o;
  FILE* pipe = popen((command + " 2>'" + errFile + "'").c_str(), "r");
  if (!pipe) return o;
  std::array<char, 4096> buffer{};
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) o.out.append(buffer.data(), n);
  const int raw = pclose(pipe);
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.err = readAndRemove(errFile);
  return o;
}

inline std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::tabletop::testing::tempDir() + name;
  std::ofstream(path) << text;
  return path;
}

inline int lineCount(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// Starts tabletop with `args`, no shell between (so hostile names reach
// it as they are), its output discarded and its errors into `errFile`;
// `inChild` runs in the child first (limits, environment).
inline pid_t start(const std::vector<std::string>& args, const std::string& errFile,
                   const std::function<void()>& inChild = {}) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (inChild) inChild();
    const int out = open("/dev/null", O_WRONLY), err = open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, 1);
    dup2(err, 2);
    std::vector<char*> argv;
    const std::string bin = kBin + "tabletop";
    argv.push_back(const_cast<char*>(bin.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(bin.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

inline std::vector<std::string> filesIn(const std::string& dir, const std::string& suffix) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      found.push_back(e.path().string());
    }
  }
  return found;
}

// What a process started by start() returned for a signal that ended it.
constexpr int kKilledBy = 1000;

// Waits for a process started by start(): its exit status, or kKilledBy
// plus the signal that ended it.
inline int finish(pid_t pid) {
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : kKilledBy + WTERMSIG(raw);
}

// Runs tabletop with `args` (no shell) to its end: status and errors.
inline Outcome runArgs(const std::vector<std::string>& args) {
  const std::string errFile = ::tabletop::testing::tempDir() + "tabletop_args_stderr_" + std::to_string(getpid()) + ".txt";
  Outcome o;
  o.status = finish(start(args, errFile));
  o.err = readAndRemove(errFile);
  return o;
}

}  // namespace tabletop::testing
