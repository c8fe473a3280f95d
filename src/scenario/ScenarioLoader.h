#pragma once

#include <string>

#include "scenario/Scenario.h"

namespace tabletop {

/// Reads scenario files (JSON with comments; SI units, degrees, Y up; see
/// scenarios/README.md). Every field is checked for type, range and
/// finiteness, unknown and repeated keys and dangling references are
/// reported, and all problems found are thrown together as one
/// ScenarioError. A file may come from anyone: what it can ask for is
/// bounded by the limits below, each refused with a located message.
class ScenarioLoader {
 public:
  static constexpr std::size_t kMaxFileBytes = 16u << 20;  ///< a scenario file's size
  static constexpr int kMaxDepth = 64;                     ///< arrays and objects inside each other
  static constexpr std::size_t kMaxEntities = 10000;
  static constexpr std::size_t kMaxActions = 100000;       ///< script entries
  static constexpr std::size_t kMaxNameBytes = 64;         ///< an entity's name (UTF-8 bytes)
  static constexpr std::size_t kMaxTextBytes = 4096;       ///< the scenario's name and description
  /// A value a message quotes is cut to this many bytes (and says how many
  /// more there were).
  static constexpr std::size_t kMaxQuotedBytes = 40;
  /// Steps x max_substeps x iterations x entities: the most solver work one
  /// run may ask for (about an hour at the slowest).
  static constexpr double kMaxWork = 1e11;

  /// Reads and checks the scenario at `path`: a regular file, a pipe, or
  /// standard input for "-", at most kMaxFileBytes of it.
  static Scenario loadFile(const std::string& path);
  /// How errors and outputs name the scenario read from `path`: "<stdin>"
  /// for "-", else the path.
  static std::string sourceName(const std::string& path);
  /// Checks `text`, naming it `source` in errors.
  static Scenario loadText(const std::string& text, const std::string& source);
  /// Empty when `settings` asks for at most kMaxSteps steps and kMaxWork
  /// work for `entities` bodies; else what is wrong (the command line's
  /// overrides are checked with it too).
  static std::string runSizeProblem(const Settings& settings, std::size_t entities);
  /// Empty when `steps` steps of `settings` for `entities` bodies ask for
  /// at most kMaxWork work; else what is wrong. runSizeProblem's second
  /// half, and the bound on a stepping call from Python.
  static std::string workProblem(double steps, const Settings& settings, std::size_t entities);
};

}  // namespace tabletop
