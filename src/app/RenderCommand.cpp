#include "app/RenderCommand.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <iomanip>
#include <regex>
#include <sstream>

#include <CLI/CLI.hpp>

#include "app/InterruptGuard.h"
#include "app/OptionChecks.h"
#include "core/Text.h"
#include "draw/Camera.h"
#include "draw/SceneDrawing.h"
#include "headless/OsMesaContext.h"
#include "headless/VideoEncoder.h"
#include "image/PngFile.h"
#include "io/FolderLock.h"
#include "render/GlRenderer.h"
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

// The scene, its script player, the offscreen context and the renderer of
// one render command.
class FrameMaker {
 public:
  FrameMaker(const Scenario& scenario, const Settings& settings, const RenderOptions& options, const Camera& camera,
             int width, int height)
      : scenario_(scenario),
        options_(options),
        camera_(camera),
        simulation_(buildSimulation(scenario, settings, options.run.mode)),
        player_(scenario, settings, *simulation_),
        context_(width, height),
        renderer_(context_.gl()) {
    player_.runDue();
  }

  /// Steps until `t` (or the end of the run) and writes the frame to `path`.
  void frameAt(double t, const std::string& path) {
    while (simulation_->time() < t - kTimeSlack && !player_.finished()) player_.step();
    DrawOptions drawOptions;
    drawOptions.arrow = options_.arrow;
    drawOptions.contacts = options_.contacts;
    const DrawList list = makeDrawList(scenario_, simulation_->snapshot(), player_.arrow(),
                                       simulation_->contactPoints(), drawOptions);
    renderer_.draw(list, camera_, context_.width(), context_.height());
    writePng(renderer_.readPixels(context_.width(), context_.height()), path);
  }

  bool finished() const { return player_.finished(); }
  double time() const { return simulation_->time(); }

 private:
  const Scenario& scenario_;
  const RenderOptions& options_;
  Camera camera_;
  std::unique_ptr<Simulation> simulation_;
  ScriptPlayer player_;
  OsMesaContext context_;
  GlRenderer renderer_;
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
  command.add_option("--out", options.outDir, "Directory for the PNG frames (made if missing)")->required();
  CLI::Option* at = command.add_option("--at", options.at, "Stills at these simulated times, seconds (T1,T2,...)")
                        ->delimiter(',')
                        ->check(finiteRange(0.0, 3600.0));
  CLI::Option* fps =
      command.add_option("--fps", options.fps, "Frames per simulated second, from 0 to the end of the run (default 30)")
          ->check(finiteRange(0.1, 1000.0));
  at->excludes(fps);
  command.add_option("--size", options.size, "Image size in pixels, WxH (default 960x720)");
  command.add_option("--camera", options.camera, "View: front (the report's), corner, side or top")
      ->check(CLI::IsMember(Camera::names()));
  command.add_option("--video", options.video, "Also encode the frames with ffmpeg into FILE.mp4 or FILE.gif")
      ->excludes(at);
  command.add_flag("!--no-arrow", options.arrow, "Hide the push arrow (the report's Push Direction Off)");
  command.add_flag("--contacts", options.contacts, "Draw contact points");
}

int renderScenario(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  const auto size = parseImageSize(options.size);
  if (!size) {
    err << "tabletop render: --size: expected WxH with each side 1..8192 pixels, got '" << options.size << "'\n";
    return kExitBadInput;
  }
  if (options.video) {
    if (const auto problem = videoNameProblem(*options.video)) {
      err << "tabletop render: " << *problem << "\n";
      return kExitBadInput;
    }
  }

  // The scene and the context come first: a bad scene is refused before
  // any directory or file is made.
  const auto start = std::chrono::steady_clock::now();
  Scenario scenario;
  std::unique_ptr<FrameMaker> maker;
  try {
    scenario = loadScenario(options.run.scenarios.front(), options.run);
    maker = std::make_unique<FrameMaker>(scenario, scenario.settings, options, *Camera::named(options.camera, scenario.table),
                                         size->first, size->second);
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

  std::error_code ec;
  std::filesystem::create_directories(options.outDir, ec);
  if (ec || !std::filesystem::is_directory(options.outDir)) {
    err << "tabletop render: --out: cannot make the directory '" << shownText(options.outDir) << "'"
        << (ec ? ": " + ec.message() : std::string()) << "\n";
    return kExitFailure;
  }

  const std::filesystem::path dir(options.outDir);
  // One render at a time writes into a folder: the lock on the folder is
  // the kernel's, so it goes with a render that is killed, and what is
  // left then can only be a killed render's.
  const FolderLock lock(options.outDir);
  if (!lock.held()) {
    err << "tabletop render: --out: another render is writing into '" << shownText(options.outDir) << "'\n";
    return kExitFailure;
  }
  if (const int removed = removeKilledTemporaries(dir); removed > 0) {
    err << "tabletop render: removed " << removed << " temporary " << (removed == 1 ? "file" : "files")
        << " that a killed render left in " << shownText(options.outDir) << "\n";
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
    if (!options.at.empty()) {
      std::vector<double> times = options.at;
      std::sort(times.begin(), times.end());
      times.erase(std::unique(times.begin(), times.end()), times.end());
      for (double t : times) {
        if (interrupt.requested()) break;
        maker->frameAt(t, (dir / stillName(t)).string());
        ++frames;
      }
    } else {
      // Old frames beyond this run's last would join a video of it.
      for (long k = 0; std::filesystem::remove(dir / frameName(k)); ++k) {
      }
      double end = std::numeric_limits<double>::infinity();
      for (long k = 0; k / options.fps <= end + kTimeSlack && !interrupt.requested(); ++k) {
        maker->frameAt(k / options.fps, (dir / frameName(k)).string());
        ++frames;
        if (maker->finished() && !std::isfinite(end)) end = maker->time() + kHoldSeconds;
      }
    }
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) err << line << "\n";
    return kExitBadInput;
  } catch (const DivergenceError& e) {
    err << scenario.file << ": " << e.what() << "; the " << frames << (frames == 1 ? " frame" : " frames")
        << " before it in " << shownText(options.outDir) << dropOldVideo() << "\n";
    return kExitDiverged;
  } catch (const std::runtime_error& e) {
    err << "tabletop render: " << e.what() << "\n";
    return kExitFailure;
  }
  if (interrupt.requested()) {
    err << "tabletop render: interrupted after " << frames << (frames == 1 ? " frame" : " frames")
        << ", each complete, in " << shownText(options.outDir) << (options.video ? "; no video made" : "")
        << dropOldVideo() << "\n";
    return kExitInterrupted;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << scenario.name << ": " << frames << (frames == 1 ? " frame" : " frames") << " of " << size->first << "x"
      << size->second << " (camera " << options.camera << ", mode " << toString(options.run.mode) << ") in "
      << options.outDir << ", " << wall << " s wall\n";

  if (options.video) {
    const auto problem = encodeVideo((dir / "frame_%05d.png").string(), options.fps, *options.video);
    if (problem) {
      err << "tabletop render: " << *problem << "; the frames are in " << options.outDir << "\n";
      return ffmpegAvailable() ? kExitFailure : kExitOk;
    }
    out << "video " << *options.video << "\n";
  }
  return kExitOk;
}

}  // namespace tabletop
