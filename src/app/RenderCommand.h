#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/RunCommand.h"

namespace tabletop {

/// What `tabletop render` was asked to do.
struct RenderOptions {
  RunOptions run;                     ///< one scenario, --mode and the setting overrides
  std::string outDir;                 ///< --out-dir: the frames' folder (none: a video alone)
  std::vector<double> at;             ///< --at: stills at these simulated times, seconds
  double fps = 30.0;                  ///< --fps: frames per simulated second, when no --at
  std::string size = "960x720";       ///< --size WxH, pixels
  std::string camera = "fit";         ///< --camera: a CameraChoice
  std::optional<std::string> video;   ///< --video FILE.mp4|FILE.gif
  bool keepFrames = false;            ///< --keep-frames: keep a video's frames in --out
  bool arrow = true;                  ///< the report's Push Direction On/Off
  bool contacts = false;              ///< draw contact points
};

/// Declares render's options and flags on `command`.
void addRenderOptions(CLI::App& command, RenderOptions& options);

/// Plays the scenario's script in the chosen mode and renders frames with
/// OSMesa, no display needed: stills at the --at times (DIR/t_1.250.png),
/// or every 1/fps simulated seconds from 0 until the run ends plus half a
/// second (DIR/frame_00000.png, ...), then with --video encodes those with
/// ffmpeg (without --out-dir the frames go to a temporary folder; with --out-dir
/// they are removed after encoding unless --keep-frames). The camera is
/// fitted over the whole run unless --camera says otherwise. On a terminal
/// a progress bar shows the frames, then the encoding. Statuses:
/// kExitBadInput for a bad scenario or option; kExitFailure when a file
/// cannot be written, OSMesa fails, or a video alone is asked for without
/// ffmpeg. Without ffmpeg and with --out-dir it says so in one line and keeps
/// the frames (status 0).
int renderScenario(const RenderOptions& options, std::ostream& out, std::ostream& err);

/// Parses "WxH" into a width and a height in 1..8192; empty if malformed.
std::optional<std::pair<int, int>> parseImageSize(const std::string& text);

}  // namespace tabletop
