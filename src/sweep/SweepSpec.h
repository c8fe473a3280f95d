#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/SimulationMode.h"
#include "scenario/JsonLocator.h"

namespace tabletop {

/// One varied parameter of a sweep: the same value written at each of its
/// JSON pointers into the scene, taken from a list, a range, or drawn at
/// random (uniform or normal) from the sweep's seed.
struct SweepParameter {
  enum class Kind { List, Uniform, Normal };
  std::string name;                   ///< the table's column ("angle"), default the first pointer
  std::vector<std::string> pointers;  ///< where in the scene the value goes
  Kind kind = Kind::List;
  std::vector<nlohmann::json> values;  ///< List: the values in order (a range is expanded)
  double a = 0.0, b = 0.0;            ///< Uniform: low, high; Normal: mean, standard deviation
  std::string at;                     ///< its pointer in the spec ("/parameters/1")
};

/// What each row records besides the run and its parameters.
struct SweepRecord {
  bool positions = true;  ///< each entity's final x, y, z, yaw, status per mode
  bool events = true;     ///< each mode's events, as one text
  bool distance = true;   ///< per mode but the rules: distance from the rules' outcome and compare's verdict
  bool cost = true;       ///< each mode's wall time
  bool stateHash = true;  ///< each mode's state_hash
};

/// The random stability runs (hard case 9, measure/RandomRunCheck.h) in
/// place of a scene and its parameters: run k is RandomScene's scene for
/// the sweep's seed + k, run in full physics and judged.
struct SweepRandom {
  std::size_t runs = 0;
  double rate = 0.0;  ///< steps per second, Hz; 0: the default settings' step
};

/// A checked sweep spec (the format: docs/sweep.md; data/schema/sweep.schema.json):
/// a base scene, the parameters varied over it, the modes, what to record.
/// The runs are the grid of the listed parameters (the first varying
/// slowest), each repeated `samples` times with fresh random draws; or,
/// with `random`, the random stability runs from `seed` on.
struct SweepSpec {
  static constexpr std::size_t kMaxFileBytes = 1u << 20;  ///< a spec file's size
  static constexpr int kMaxDepth = 32;                    ///< nesting in a spec
  static constexpr std::size_t kMaxParameters = 16;
  static constexpr std::size_t kMaxPointers = 64;    ///< pointers of one parameter, and entries of "set"
  static constexpr std::size_t kMaxValues = 10000;   ///< values of one list, count of one range
  static constexpr std::size_t kMaxRuns = 100000;    ///< runs of one sweep
  static constexpr std::size_t kMaxEntities = 100;   ///< entities of the base scene (the row's width)
  static constexpr std::size_t kMaxSceneBytes = 1u << 20;  ///< the base scene, written as JSON
  static constexpr std::size_t kMaxNameBytes = 64;   ///< the sweep's and a parameter's name

  std::string name;
  std::string file;              ///< where the spec was read from
  nlohmann::json scene;          ///< the base scene, with "set" applied
  std::string sceneSource;       ///< where the base scene came from
  std::vector<SweepParameter> parameters;
  std::size_t samples = 1;
  std::uint64_t seed = 0;
  std::vector<SimulationMode> modes;  ///< in the order rules, compat, bullet
  SweepRecord record;
  std::vector<std::string> entities;  ///< the base scene's entity names
  std::optional<SweepRandom> random;  ///< the random runs, in place of scene and parameters
  std::shared_ptr<const JsonLocator> locator;

  /// How many runs the sweep has.
  std::size_t runs() const;
  /// Run `index`'s value of each parameter (the same in every process);
  /// of the random runs, its seed.
  std::vector<nlohmann::json> valuesOf(std::size_t index) const;
  /// The columns valuesOf() fills: the parameters' names, or "seed".
  std::vector<std::string> valueNames() const;
  /// Run `index`'s scene as JSON text.
  std::string sceneOf(std::size_t index) const;
  /// The spec as one JSON document with the scene inlined, which loads
  /// anywhere without its files (what a cluster's workers are sent).
  std::string selfContained() const;
};

/// Reads and checks a spec: every problem thrown together as one
/// ScenarioError, one located line each. A "scene" naming a file (ending in
/// .json) is read relative to the spec's folder, any other name from
/// `shippedScenes`; every run's scene is checked before anything runs,
/// unless `checkEveryRun` is false (a spec checked already where it was
/// made, sent whole to a cluster's worker that runs a few of its runs).
SweepSpec loadSweepText(const std::string& text, const std::string& source, const std::string& shippedScenes,
                        bool checkEveryRun = true);
SweepSpec loadSweepFile(const std::string& path, const std::string& shippedScenes);

}  // namespace tabletop
