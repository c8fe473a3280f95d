#include "app/RenderCommand.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <iomanip>
#include <regex>
#include <sstream>
#include <variant>

#include <CLI/CLI.hpp>

#include "app/InterruptGuard.h"
#include "app/OptionChecks.h"
#include "app/Progress.h"
#include "core/Text.h"
#include "draw/Camera.h"
#include "draw/CameraChoice.h"
#include "draw/SceneDrawing.h"
#include "headless/HeadlessFrames.h"
#include "headless/VideoEncoder.h"
#include "image/PngFile.h"
#include "io/FolderLock.h"
#include "io/TemporaryFolder.h"
#include "scenario/ScenarioError.h"
#include "sim/DivergenceGuard.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptPlayer.h"

namespace tabletop {
namespace {

constexpr double kTimeSlack = 1e-9;
// Frames at --fps go on this long after the run has ended, so a looping
// video rests on the outcome before it starts again.
constexpr double kHoldSeconds = 0.5;
// The most frames one render writes.
constexpr double kMaxFrames = 100000;
// The private folders of frames nobody asked to keep (io/TemporaryFolder.h).
constexpr const char* kFramesPrefix = "tabletop-frames-";

std::string stillName(double t) {
  std::ostringstream name;
  name << "t_" << std::fixed << std::setprecision(3) << t << ".png";
  return name.str();
}

// Removes the temporaries of frames and stills that a killed render (a
// kill cannot be caught) left in `dir`; returns how many.
int removeKilledTemporaries(const std::filesystem::path& dir) {
  // A frame's or still's temporary: "frame_00012.png.XXXXXX.part", "t_0.500.png.XXXXXX.part".
  const auto isTemporary = [](const std::string& name) {
    const std::size_t png = name.find(".png.");
    return (name.rfind("frame_", 0) == 0 || name.rfind("t_", 0) == 0) && png != std::string::npos &&
           name.size() == png + 5 + 6 + 5 && endsWith(name, ".part");
  };
  int removed = 0;
  std::error_code ec;
  for (const auto& f : std::filesystem::directory_iterator(dir, ec)) {
    if (f.is_regular_file(ec) && isTemporary(f.path().filename().string())) {
      removed += std::filesystem::remove(f.path(), ec) ? 1 : 0;
    }
  }
  return removed;
}

std::string frameName(long k) {
  char name[64];
  std::snprintf(name, sizeof name, "frame_%05ld.png", k);
  return name;
}

// The scene and its script player, stepped to each frame's time.
class Playback {
 public:
  Playback(const Scenario& scenario, const Settings& settings, SimulationMode mode)
      : simulation_(buildSimulation(scenario, settings, mode)), player_(scenario, settings, *simulation_) {
    player_.runDue();
  }
  /// Steps until `t` or the end of the run.
  void stepTo(double t) {
    while (simulation_->time() < t - kTimeSlack && !player_.finished()) player_.step();
  }
  bool finished() const { return player_.finished(); }
  double time() const { return simulation_->time(); }
  const Simulation& simulation() const { return *simulation_; }
  const ScriptPlayer& player() const { return player_; }

 private:
  std::unique_ptr<Simulation> simulation_;
  ScriptPlayer player_;
};

// The times of the frames: the stills asked for, or every 1/fps from 0 to
// the end of the run and kHoldSeconds more (which `playback` finds by
// playing the run, adding what each frame shows to `extent`). A run that
// diverges ends its frames at the one where it diverged, so the frames
// before it are drawn and the drawing meets the divergence there again.
std::vector<double> frameTimes(const RenderOptions& options, Playback& playback, const Scenario& scenario,
                               SceneExtent& extent, const InterruptGuard& interrupt) {
  std::vector<double> asked = options.at, times;
  std::sort(asked.begin(), asked.end());
  asked.erase(std::unique(asked.begin(), asked.end()), asked.end());
  double end = std::numeric_limits<double>::infinity();
  for (long k = 0; !interrupt.requested(); ++k) {
    if (asked.empty() ? k / options.fps > end + kTimeSlack : k == static_cast<long>(asked.size())) break;
    times.push_back(asked.empty() ? k / options.fps : asked[k]);
    try {
      playback.stepTo(times.back());
    } catch (const DivergenceError&) {
      break;
    }
    extent.add(sceneBounds(scenario, playback.simulation().snapshot()));
    if (playback.finished() && !std::isfinite(end)) end = playback.time() + kHoldSeconds;
  }
  return times;
}

// The offscreen context and the renderer of one render command, drawing
// the frames of its own playback of the scene.
class FrameMaker {
 public:
  FrameMaker(const Scenario& scenario, const Settings& settings, const RenderOptions& options,
             const CameraChoice& camera, int width, int height)
      : scenario_(scenario),
        options_(options),
        camera_(camera),
        playback_(scenario, settings, options.run.mode),
        frames_(width, height) {}

  /// Steps until `t` (or the end of the run) and writes the frame to `path`.
  void frameAt(double t, const SceneExtent& extent, const std::string& path) {
    playback_.stepTo(t);
    DrawOptions drawOptions;
    drawOptions.arrow = options_.arrow;
    drawOptions.contacts = options_.contacts;
    // The floor reaches under everything the run's frames show.
    drawOptions.floorReach = 1.5 * extent.reachFrom(scenario_.table.centreX, scenario_.table.centreZ);
    const std::vector<EntityState> states = playback_.simulation().snapshot();
    const DrawList list = makeDrawList(scenario_, states, playback_.player().arrow(),
                                       playback_.simulation().contactPoints(), drawOptions);
    const Camera camera = cameraFor(camera_, scenario_, states, extent, double(frames_.width()) / frames_.height());
    writePng(frames_.draw(list, camera), path);
  }

 private:
  const Scenario& scenario_;
  const RenderOptions& options_;
  const CameraChoice& camera_;
  Playback playback_;
  HeadlessFrames frames_;
};

}  // namespace

std::optional<std::pair<int, int>> parseImageSize(const std::string& text) {
  static const std::regex pattern("([0-9]{1,5})x([0-9]{1,5})");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return std::nullopt;
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1 || w > 8192 || h > 8192) return std::nullopt;
  return std::make_pair(w, h);
}

void addRenderOptions(CLI::App& command, RenderOptions& options) {
  command.add_option("--out-dir", options.outDir,
                     "Folder for the PNG frames (made if missing); needed unless --video is given");
  CLI::Option* at = command.add_option("--at", options.at, "Stills at these simulated times, seconds (T1,T2,...)")
                        ->delimiter(',')
                        ->check(finiteRange(0.0, 3600.0));
  CLI::Option* fps =
      command.add_option("--fps", options.fps, "Frames per simulated second, from 0 to the end of the run (default 30)")
          ->check(finiteRange(0.1, 1000.0));
  at->excludes(fps);
  command.add_option("--size", options.size, "Image size in pixels, WxH (default " + options.size + ")");
  command.add_option("--camera", options.camera, CameraChoice::help())
      ->check(cameraChoice());
  CLI::Option* video =
      command.add_option("--video", options.video, "Encode the frames with ffmpeg into FILE.mp4 or FILE.gif")
          ->excludes(at);
  command.add_flag("--keep-frames", options.keepFrames, "With --video, keep the frames in --out-dir (default: removed)")
      ->needs(video);
  command.add_flag("!--no-arrow", options.arrow, "Hide the push arrow (the report's Push Direction Off)");
  command.add_flag("--contacts", options.contacts, "Draw contact points");
}

int renderScenario(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  const auto size = parseImageSize(options.size);
  if (!size) {
    err << "tabletop render: --size: expected WxH with each side 1..8192 pixels, got '" << options.size << "'\n";
    return kExitBadInput;
  }
  const auto parsed = CameraChoice::parse(options.camera);
  if (const auto* why = std::get_if<std::string>(&parsed)) {
    err << "tabletop render: --camera: " << *why << "\n";
    return kExitBadInput;
  }
  const CameraChoice& camera = std::get<CameraChoice>(parsed);
  if (options.outDir.empty() && !options.video) {
    err << "tabletop render: --out-dir: expected a folder for the frames (or --video FILE for a video alone)\n";
    return kExitBadInput;
  }
  if (options.keepFrames && options.outDir.empty()) {
    err << "tabletop render: --keep-frames: expected --out-dir DIR to keep them in\n";
    return kExitBadInput;
  }
  // The frames' folder is named in every frame's path: printable, as every
  // output's name (io/AtomicFile.h), checked before it is made.
  if (const auto unprintable = unprintableProblem(options.outDir)) {
    err << "tabletop render: --out-dir: '" << shownText(options.outDir, 256) << "': expected a printable folder name, got "
        << *unprintable << "\n";
    return kExitBadInput;
  }
  if (options.video) {
    if (const auto problem = videoNameProblem(*options.video)) {
      err << "tabletop render: " << *problem << "\n";
      return kExitBadInput;
    }
    if (options.outDir.empty() && !ffmpegAvailable()) {
      err << "tabletop render: --video: ffmpeg is not installed (apt-get install ffmpeg); --out-dir DIR writes the "
             "frames alone\n";
      return kExitFailure;
    }
  }

  // The scene and the context come first: a bad scene is refused before
  // any directory or file is made.
  const auto start = std::chrono::steady_clock::now();
  Scenario scenario;
  std::unique_ptr<FrameMaker> maker;
  try {
    scenario = loadScenario(options.run.scenarios.front(), options.run);
    if (const std::string problem = camera.problemWith(scenario); !problem.empty()) {
      err << "tabletop render: --camera: " << problem << "\n";
      return kExitBadInput;
    }
    maker = std::make_unique<FrameMaker>(scenario, scenario.settings, options, camera, size->first, size->second);
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) err << line << "\n";
    return kExitBadInput;
  } catch (const std::runtime_error& e) {
    err << "tabletop render: " << e.what() << "\n";
    return kExitFailure;
  }

  const Settings& settings = scenario.settings;
  if (options.at.empty() && options.fps * (settings.duration + kHoldSeconds) > kMaxFrames) {
    err << "tabletop render: --fps: expected at most " << kMaxFrames << " frames (fps x (duration + "
        << kHoldSeconds << " s)), got " << options.fps * (settings.duration + kHoldSeconds) << "\n";
    return kExitBadInput;
  }

  // Frames nobody asked to keep go to a private folder removed at the end;
  // those of renders killed before they could remove theirs go first.
  for (const std::string& left : TemporaryFolder::removeAbandoned(kFramesPrefix)) {
    err << "tabletop render: removed " << shownText(left, 1024) << ", the frames of a killed render\n";
  }
  std::unique_ptr<TemporaryFolder> scratch;
  std::string frameDir = options.outDir;
  if (frameDir.empty()) {
    try {
      scratch = std::make_unique<TemporaryFolder>(kFramesPrefix);
    } catch (const std::runtime_error& e) {
      err << "tabletop render: " << e.what() << "\n";
      return kExitFailure;
    }
    frameDir = scratch->path();
  }
  const std::string shownDir = options.outDir.empty() ? std::string("no folder") : shownText(options.outDir);

  std::error_code ec;
  std::filesystem::create_directories(frameDir, ec);
  if (ec || !std::filesystem::is_directory(frameDir)) {
    err << "tabletop render: --out-dir: cannot make the directory '" << shownText(frameDir) << "'"
        << (ec ? ": " + ec.message() : std::string()) << "\n";
    return kExitFailure;
  }

  const std::filesystem::path dir(frameDir);
  // One render at a time writes into a folder: the lock on the folder is
  // the kernel's, so it goes with a render that is killed, and what is
  // left then can only be a killed render's. A private folder holds its
  // own lock.
  std::optional<FolderLock> lock;
  if (!scratch) lock.emplace(frameDir);
  if (lock && !lock->held()) {
    err << "tabletop render: --out-dir: another render is writing into '" << shownText(frameDir) << "'\n";
    return kExitFailure;
  }
  if (const int removed = removeKilledTemporaries(dir); removed > 0) {
    err << "tabletop render: removed " << removed << " temporary " << (removed == 1 ? "file" : "files")
        << " that a killed render left in " << shownText(frameDir) << "\n";
  }
  // A video that stays beside frames of another run would not show them:
  // a render that stops early takes the old video away with the old frames.
  const auto dropOldVideo = [&]() -> std::string {
    if (!options.video || !std::filesystem::is_regular_file(*options.video, ec)) return "";
    std::filesystem::remove(*options.video, ec);
    return "; the old video " + shownText(*options.video) + " was removed with the old frames";
  };
  long frames = 0;
  const InterruptGuard interrupt;
  try {
    // A first playback finds the frames' times and what they show, so a
    // fitted camera frames the whole run from the first frame on.
    SceneExtent extent;
    Playback scout(scenario, settings, options.run.mode);
    const std::vector<double> times = frameTimes(options, scout, scenario, extent, interrupt);
    if (options.at.empty()) {
      // Old frames beyond this run's last would join a video of it.
      for (long k = 0; std::filesystem::remove(dir / frameName(k)); ++k) {
      }
    }
    Progress progress(err);
    progress.start(static_cast<long>(times.size()));
    for (double t : times) {
      if (interrupt.requested()) break;
      const std::string name = options.at.empty() ? frameName(frames) : stillName(t);
      maker->frameAt(t, extent, (dir / name).string());
      ++frames;
      progress.advance("frames");
    }
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) err << line << "\n";
    return kExitBadInput;
  } catch (const DivergenceError& e) {
    err << scenario.file << ": " << e.what() << "; the " << frames << (frames == 1 ? " frame" : " frames")
        << " before it in " << shownDir << dropOldVideo() << "\n";
    return kExitDiverged;
  } catch (const std::runtime_error& e) {
    err << "tabletop render: " << e.what() << "\n";
    return kExitFailure;
  }
  if (interrupt.requested()) {
    err << "tabletop render: interrupted after " << frames << (frames == 1 ? " frame" : " frames")
        << ", each complete, in " << shownDir << (options.video ? "; no video made" : "") << dropOldVideo() << "\n";
    return kExitInterrupted;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << scenario.name << ": " << frames << (frames == 1 ? " frame" : " frames") << " of " << size->first << "x"
      << size->second << " (camera " << options.camera << ", mode " << toString(options.run.mode) << ")"
      << (options.outDir.empty() ? std::string() : " in " + options.outDir) << ", " << wall << " s wall\n";

  if (options.video) {
    std::optional<std::string> problem;
    {
      Progress encoding(err);
      encoding.start(frames);
      const std::string what = "encoding " + shownText(*options.video);
      problem = encodeVideo((dir / "frame_%05d.png").string(), options.fps, *options.video,
                            [&encoding, &what](long done) { encoding.set(done, what); },
                            [&interrupt] { return interrupt.requested(); });
    }
    // Ctrl-C reaches ffmpeg too, SIGTERM only tabletop: either way the
    // video is left as it was, the last whole one.
    if (interrupt.requested()) {
      err << "tabletop render: interrupted while encoding; " << shownText(*options.video)
          << " left as it was" << (options.outDir.empty() ? "" : "; the frames are in " + shownDir) << "\n";
      return kExitInterrupted;
    }
    if (problem) {
      err << "tabletop render: " << *problem << (options.outDir.empty() ? "" : "; the frames are in " + shownDir)
          << "\n";
      return ffmpegAvailable() ? kExitFailure : kExitOk;
    }
    out << "video " << *options.video << "\n";
    if (!options.outDir.empty() && !options.keepFrames) {
      for (long k = 0; k < frames; ++k) std::filesystem::remove(dir / frameName(k), ec);
    }
  }
  return kExitOk;
}

}  // namespace tabletop
