#pragma once

#include <string>

#include "scenario/Scenario.h"

namespace tabletop {

/// Reads scenario files (JSON with comments; SI units, degrees, Y up; see
/// scenarios/README.md). Every field is checked for type, range and
/// finiteness, unknown keys and dangling references are reported, and all
/// problems found are thrown together as one ScenarioError.
class ScenarioLoader {
 public:
  /// Reads and checks the file at `path`.
  static Scenario loadFile(const std::string& path);
  /// Checks `text`, naming it `source` in errors.
  static Scenario loadText(const std::string& text, const std::string& source);
  /// Empty when `settings` asks for at most kMaxSteps steps; else what is
  /// wrong (the command line's overrides are checked with it too).
  static std::string stepCountProblem(const Settings& settings);
};

}  // namespace tabletop
