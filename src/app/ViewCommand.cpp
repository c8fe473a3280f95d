#include "app/ViewCommand.h"

#include <ostream>

#include <CLI/CLI.hpp>

#include "app/RenderCommand.h"
#include "app/OptionChecks.h"
#include "draw/CameraChoice.h"
#include "scenario/ScenarioError.h"
#include "viewer/Viewer.h"

namespace tabletop {

void addViewOptions(CLI::App& command, ViewOptions& options) {
  command.add_flag("!--no-script", options.playScript,
                   "Do not play the scenario's script on start (Enter plays it)");
  command.add_option("--step", options.step, "The step G pushes by, metres (default: the script's first step)")
      ->check(CLI::PositiveNumber);
  command.add_option("--camera", options.camera, CameraChoice::help())
      ->check(cameraChoice());
  command.add_option("--size", options.size, "Window size in pixels, WxH (default " + options.size + ")");
  command.add_option("--screenshot-dir", options.screenshotDir, "Where F12 writes screenshots (default .)");
}

int viewScenario(const ViewOptions& options, std::ostream& err) {
  const auto size = parseImageSize(options.size);
  if (!size) {
    err << "tabletop view: --size: expected WxH with each side 1..8192 pixels, got '" << options.size << "'\n";
    return kExitBadInput;
  }
  // A missing display is said before the scenario is even read.
  const std::string problem = displayProblem();
  if (!problem.empty()) {
    err << noDisplayMessage(problem) << "\n";
    return kExitFailure;
  }
  try {
    Scenario scenario = loadScenario(options.run.scenarios.front(), options.run);
    const CameraChoice camera = std::get<CameraChoice>(CameraChoice::parse(options.camera));
    if (const std::string cameraProblem = camera.problemWith(scenario); !cameraProblem.empty()) {
      err << "tabletop view: --camera: " << cameraProblem << "\n";
      return kExitBadInput;
    }
    const Settings settings = scenario.settings;
    ViewerSettings viewer;
    viewer.mode = options.run.mode;
    viewer.playScript = options.playScript;
    viewer.step = options.step;
    viewer.camera = options.camera;
    viewer.aspect = double(size->first) / size->second;
    ViewerSession session(std::move(scenario), settings, viewer);
    WindowSettings window;
    window.width = size->first;
    window.height = size->second;
    window.screenshotDir = options.screenshotDir;
    return runViewer(session, window, err) == 0 ? kExitOk : kExitFailure;
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) err << line << "\n";
    return kExitBadInput;
  }
}

}  // namespace tabletop
