#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "app/RunCommand.h"

namespace tabletop {

/// What `tabletop view` was asked to do.
struct ViewOptions {
  RunOptions run;                 ///< one scenario, --mode and the setting overrides
  bool playScript = true;         ///< --no-script: start still, play with Enter
  std::optional<double> step;     ///< --step: G's step, metres
  std::string camera = "fit";     ///< --camera: a CameraChoice
  std::string size = "960x720";   ///< --size WxH, the window (as render's frames)
  std::string screenshotDir = ".";
};

/// Declares view's options and flags on `command`.
void addViewOptions(CLI::App& command, ViewOptions& options);

/// Opens the report's window on the scenario (see Viewer.h) until it is
/// closed. Statuses: kExitBadInput for a bad scenario or option,
/// kExitFailure when there is no display.
int viewScenario(const ViewOptions& options, std::ostream& err);

}  // namespace tabletop
