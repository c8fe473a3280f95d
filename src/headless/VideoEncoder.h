#pragma once

#include <functional>
#include <optional>
#include <string>

namespace tabletop {

/// Why `out` cannot name a video (it must end in .mp4 or .gif), or empty.
std::optional<std::string> videoNameProblem(const std::string& out);

/// True when an `ffmpeg` executable is on the PATH.
bool ffmpegAvailable();

/// Encodes the numbered PNG frames `framePattern` (printf style, e.g.
/// "DIR/frame_%05d.png") played at `fps` into `out`, an .mp4 (H.264,
/// yuv420p) or a .gif (with a palette made from the frames), by running
/// ffmpeg. Writes a temporary file renamed into place. `progress`, when
/// given, is told how many frames ffmpeg has encoded, about ten times a
/// second. `stop`, asked as often, ends the encoding when it says true:
/// ffmpeg is ended and `out` keeps what it held. Returns an error message,
/// or nothing on success.
std::optional<std::string> encodeVideo(const std::string& framePattern, double fps, const std::string& out,
                                       const std::function<void(long frames)>& progress = {},
                                       const std::function<bool()>& stop = {});

}  // namespace tabletop
