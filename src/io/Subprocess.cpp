#include "io/Subprocess.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

extern char** environ;

namespace tabletop {

int runProgram(const std::vector<std::string>& args, const std::string& input, const std::string& logPath,
               const std::function<void()>& waiting, const std::function<bool()>& stop) {
  std::FILE* in = std::tmpfile();
  if (!in) return -1;
  const bool written = std::fwrite(input.data(), 1, input.size(), in) == input.size() && std::fflush(in) == 0;
  std::rewind(in);
  if (!written) {
    std::fclose(in);
    return -1;
  }
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fileno(in), 0);
  posix_spawn_file_actions_addopen(&actions, 1, logPath.empty() ? "/dev/null" : logPath.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  std::fclose(in);
  if (started != 0) return 127;
  int status = 0;
  const bool poll = waiting || stop;
  int stopTicks = -1;  // tenths of a second since it was asked to end
  for (;;) {
    const pid_t done = waitpid(pid, &status, poll ? WNOHANG : 0);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return -1;
    if (done == 0) {
      if (waiting) waiting();
      if (stopTicks < 0 && stop && stop()) {
        kill(pid, SIGTERM);
        stopTicks = 0;
      } else if (stopTicks >= 0 && ++stopTicks == 10) {
        kill(pid, SIGKILL);
      }
      usleep(100000);
    }
  }
  if (stopTicks >= 0) return kStopped;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool programAvailable(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (!dir.empty() && access((dir + "/" + name).c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string lastLineOf(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

}  // namespace tabletop
