#include "headless/VideoEncoder.h"

#include "io/AtomicFile.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

extern char** environ;

namespace tabletop {
namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Runs argv with stdin from /dev/null and stdout and stderr into `log`;
// returns the exit status, or -1 if it could not start.
int run(const std::vector<std::string>& args, const std::string& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string lastLine(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

}  // namespace

std::optional<std::string> videoNameProblem(const std::string& out) {
  if (endsWith(out, ".mp4") || endsWith(out, ".gif")) return std::nullopt;
  return "--video: expected a file name ending in .mp4 or .gif, got '" + out + "'";
}

bool ffmpegAvailable() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (!dir.empty() && access((dir + "/ffmpeg").c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::optional<std::string> encodeVideo(const std::string& framePattern, double fps, const std::string& out) {
  std::vector<std::string> args{"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate", std::to_string(fps),
                                "-i", framePattern};
  if (endsWith(out, ".mp4")) {
    // H.264 in yuv420p needs even sides; +faststart lets players start at once.
    args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                             "-movflags", "+faststart", "-f", "mp4"});
  } else if (endsWith(out, ".gif")) {
    // One palette made from all the frames keeps the colours true.
    args.insert(args.end(), {"-filter_complex", "[0:v]split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse",
                             "-f", "gif"});
  } else {
    return videoNameProblem(out);
  }
  if (!ffmpegAvailable()) return "ffmpeg is not installed, so no video was made (apt-get install ffmpeg)";
  AtomicFile file(out);
  const std::string log = out + ".log.part";
  args.push_back(file.temporaryPath());
  const int status = run(args, log);
  const std::string why = lastLine(log);
  std::remove(log.c_str());
  if (status != 0) return "ffmpeg could not encode " + out + (why.empty() ? std::string() : ": " + why);
  const std::string problem = file.commit();
  if (!problem.empty()) return problem;
  return std::nullopt;
}

}  // namespace tabletop
