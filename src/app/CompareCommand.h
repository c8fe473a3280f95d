#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "app/RunCommand.h"

namespace tabletop {

/// What `tabletop compare` was asked to do.
struct CompareOptions {
  RunOptions run;                   ///< one scenario; --json and the setting overrides
  std::optional<std::string> plot;  ///< --plot FILE (.png or .svg)
};

/// Runs the scenario in the rules, compat and bullet modes, prints each
/// entity's outcome per mode with its distance from the rules' and a
/// verdict, and with --plot draws the trajectories. Statuses as for run;
/// a plot that cannot be written is kExitFailure after the comparison is
/// printed.
int compareScenario(const CompareOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tabletop
