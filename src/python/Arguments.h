#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "core/SimulationMode.h"
#include "scenario/Scenario.h"
#include "scenario/ValueRanges.h"

/// The module's arguments checked before anything changes, against the
/// ranges a scenario file is checked against (scenario/ValueRanges.h) and
/// in the same words, each refusal a ValueError naming the argument:
/// "push: impulse: expected a positive number up to 1e+06, got nan".
namespace tabletop::python {

namespace py = pybind11;

/// An image's side, pixels: render's --size allows each side 1..8192.
inline constexpr int kMaxImageSide = 8192;

/// `value`, or a ValueError "`what`: expected ..., got `value`".
double checkedNumber(const std::string& what, double value, const ranges::Range& range);
/// An integer (anything with __index__: int, bool, NumPy's integers) from
/// `lo` to `hi`; a TypeError for anything else, a ValueError out of range
/// (however large), "`what`: expected an integer from lo to hi, got v".
long long checkedInteger(const std::string& what, const py::handle& value, long long lo, long long hi);
/// The name of one of the scene's entities, as the loader checks a
/// script's: "`what`: expected the name of an entity, got "X"".
const std::string& checkedEntity(const std::string& what, const Scenario& scenario, const std::string& name);
/// An entity named (str) or by its index in the arrays (an integer; negative
/// counts from the end, as Python's indexing): its name. A TypeError for
/// anything else, a ValueError for no such entity.
const std::string& checkedEntity(const std::string& what, const Scenario& scenario, const py::handle& entity);
/// Three finite numbers (a list, tuple or NumPy array), each within
/// `range`: "`what`: expected 3 numbers ..." otherwise.
Vec3 checkedVector(const std::string& what, const py::handle& value, const ranges::Range& range);

SimulationMode modeNamed(const std::string& name);

/// What the Python side may override of a scenario's settings, as `run`'s
/// options do. None leaves the scenario's own.
struct Overrides {
  std::optional<double> timestep;
  py::object iterations = py::none();
  std::optional<std::string> integrator;
  std::optional<double> duration;
  /// Threads the step solves islands on: None reads TABLETOP_THREADS, and
  /// without it takes every core (as the command line).
  py::object threads = py::none();
};

/// `scenario` with `overrides` applied: each checked against its setting's
/// range, and the whole against the loader's bound on a run's size (a
/// ScenarioError at /settings).
Scenario resolved(Scenario scenario, const Overrides& overrides);

/// A Scenario, a file's path or a shipped scene's name (str or
/// os.PathLike), or a scene's objects (checked as a file is, located in
/// that object written as JSON).
Scenario scenarioOf(const py::object& scene);
/// Reads and checks the file at `path`, else the shipped scene of that
/// name (sceneFile, scenario/ShippedScenes.h). A path holding a NUL is
/// refused: the file system would read a shorter one.
Scenario loadPath(const std::string& path);

/// Where the module finds the shipped scenes: dataFolder's rule
/// (TABLETOP_DATA_DIR; else PREFIX/share/tabletop when the module is
/// installed under PREFIX; else the source tree it was built from), then
/// scenarios/.
std::string shippedScenes();

/// A JSON value as Python objects (dicts, lists, numbers, strings).
py::object fromJson(const nlohmann::json& value);

}  // namespace tabletop::python
