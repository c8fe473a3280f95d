#include "headless/VideoEncoder.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/Subprocess.h"

namespace tabletop {

std::optional<std::string> videoNameProblem(const std::string& out) {
  if (!endsWith(out, ".mp4") && !endsWith(out, ".gif")) {
    return "--video: expected a file name ending in .mp4 or .gif, got '" + shownText(out) + "'";
  }
  if (std::string problem = AtomicFile::destinationProblem(out); !problem.empty()) return "--video: " + problem;
  return std::nullopt;
}

bool ffmpegAvailable() { return programAvailable("ffmpeg"); }

std::optional<std::string> encodeVideo(const std::string& framePattern, double fps, const std::string& out,
                                       const std::function<void(long frames)>& progress,
                                       const std::function<bool()>& stop) {
  // Every argument is one argv entry: a frame or video name is never parsed
  // by a shell. "-i" names the frames by a pattern ffmpeg expands itself.
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
  if (!file.problem().empty()) return file.problem();
  // "file:" keeps a name that starts like a protocol ("http:") a file name.
  args.push_back("file:" + file.temporaryPath());
  const std::string log = file.temporaryPath() + ".log";
  // ffmpeg writes "frame=N" lines, among others, to its progress file.
  const std::string progressFile = file.temporaryPath() + ".progress";
  if (progress) args.insert(args.begin() + 1, {"-progress", "file:" + progressFile});
  const auto report = [&progress, &progressFile] {
    std::ifstream in(progressFile);
    std::string line;
    long frames = -1;
    while (std::getline(in, line)) {
      if (line.rfind("frame=", 0) == 0) frames = std::strtol(line.c_str() + 6, nullptr, 10);
    }
    if (frames >= 0) progress(frames);
  };
  const int status =
      runProgram(args, "", log, progress ? std::function<void()>(report) : std::function<void()>(), stop);
  const std::string why = lastLineOf(log);
  std::remove(log.c_str());
  std::remove(progressFile.c_str());
  if (status == kStopped) return "stopped encoding " + shownText(out) + "; it was left as it was";
  if (status != 0) {
    return "ffmpeg could not encode " + shownText(out) + (why.empty() ? std::string() : ": " + shownText(why, 200));
  }
  const std::string problem = file.commit();
  if (!problem.empty()) return problem;
  return std::nullopt;
}

}  // namespace tabletop
