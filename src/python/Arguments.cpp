#include "python/Arguments.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "core/Integrator.h"
#include "core/Text.h"
#include "core/WorkerThreads.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "scenario/ShippedScenes.h"

namespace tabletop::python {

double checkedNumber(const std::string& what, double value, const ranges::Range& range) {
  if (!ranges::inRange(value, range)) {
    throw py::value_error(what + ": expected " + ranges::expectedText(value, range) + ", got " +
                          ranges::number(value));
  }
  return value;
}

long long checkedInteger(const std::string& what, const py::handle& value, long long lo, long long hi) {
  const std::string expected = "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
  // PyNumber_Index takes what Python's own range() takes, and refuses
  // floats (1.5 steps is no number of steps).
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!index) {
    PyErr_Clear();
    throw py::type_error(what + ": " + expected + ", got " + shownText(py::repr(value).cast<std::string>(), 40));
  }
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  if (overflow != 0 || v < lo || v > hi) {
    throw py::value_error(what + ": " + expected + ", got " + shownText(py::str(index).cast<std::string>(), 40));
  }
  return v;
}

const std::string& checkedEntity(const std::string& what, const Scenario& scenario, const std::string& name) {
  for (const EntitySpec& e : scenario.entities) {
    if (e.name == name) return e.name;
  }
  throw py::value_error(what + ": expected the name of an entity, got \"" + shownText(name, 40) + "\"");
}

const std::string& checkedEntity(const std::string& what, const Scenario& scenario, const py::handle& entity) {
  if (py::isinstance<py::str>(entity)) return checkedEntity(what, scenario, entity.cast<std::string>());
  if (PyBool_Check(entity.ptr()) || !PyIndex_Check(entity.ptr())) {
    throw py::type_error(what + ": expected an entity's name or index, got " +
                         shownText(py::repr(entity).cast<std::string>(), 40));
  }
  const auto n = static_cast<long long>(scenario.entities.size());
  long long i = checkedInteger(what, entity, -n, n - 1);
  if (i < 0) i += n;
  return scenario.entities[static_cast<std::size_t>(i)].name;
}

Vec3 checkedVector(const std::string& what, const py::handle& value, const ranges::Range& range) {
  const std::string expected = what + ": expected 3 numbers";
  if (py::isinstance<py::str>(value) || !PySequence_Check(value.ptr()) || PySequence_Size(value.ptr()) != 3) {
    if (PyErr_Occurred()) PyErr_Clear();
    throw py::type_error(expected + ", got " + shownText(py::repr(value).cast<std::string>(), 40));
  }
  double c[3];
  for (int k = 0; k < 3; ++k) {
    const py::object item = py::reinterpret_borrow<py::sequence>(value)[k];
    if (!PyFloat_Check(item.ptr()) && !PyIndex_Check(item.ptr()) && !py::hasattr(item, "__float__")) {
      throw py::type_error(expected + ", got " + shownText(py::repr(value).cast<std::string>(), 40));
    }
    c[k] = checkedNumber(what + "[" + std::to_string(k) + "]", py::float_(item).cast<double>(), range);
  }
  return {c[0], c[1], c[2]};
}

SimulationMode modeNamed(const std::string& name) {
  const auto mode = simulationModeFromString(name);
  if (!mode) throw py::value_error("mode: expected bullet, compat or rules, got '" + shownText(name, 40) + "'");
  return *mode;
}

Scenario resolved(Scenario scenario, const Overrides& o) {
  Settings& s = scenario.settings;
  if (o.timestep) s.timestep = checkedNumber("timestep", *o.timestep, ranges::kTimestep);
  if (!o.iterations.is_none()) {
    s.iterations = static_cast<int>(
        checkedInteger("iterations", o.iterations, ranges::kIterations.lo, ranges::kIterations.hi));
  }
  if (o.integrator) {
    const auto integrator = integratorFromString(*o.integrator);
    if (!integrator) {
      throw py::value_error("integrator: expected trapezoid or euler, got '" + shownText(*o.integrator, 40) + "'");
    }
    s.integrator = *integrator;
  }
  if (o.duration) s.duration = checkedNumber("duration", *o.duration, ranges::kSpan);
  if (!o.threads.is_none()) {
    s.threads = static_cast<int>(checkedInteger("threads", o.threads, 1, kMaxThreads));
  } else if (const char* environment = std::getenv("TABLETOP_THREADS")) {
    const std::optional<int> n = threadCount(environment);
    if (!n) {
      throw py::value_error("threads: TABLETOP_THREADS: expected a whole number from 1 to " +
                            std::to_string(kMaxThreads) + ", got '" + shownText(environment, 40) + "'");
    }
    s.threads = *n;
  } else {
    s.threads = availableThreads();
  }
  if (const std::string problem = ScenarioLoader::runSizeProblem(s, scenario.entities.size()); !problem.empty()) {
    throw ScenarioError(scenario, {{"/settings", problem + " with the settings given from Python"}});
  }
  return scenario;
}

Scenario loadPath(const std::string& path) {
  if (path.find('\0') != std::string::npos) {
    throw py::value_error("path: expected a file's path, got one holding a NUL character");
  }
  return ScenarioLoader::loadFile(sceneFile(path, shippedScenes(), "tabletop.shipped_scenes()"));
}

std::string shippedScenes() {
  // The module's own file, found from one of its functions: installed, it
  // is TABLETOP_PYTHON_INSTALL_DIR under the prefix, and the data
  // TABLETOP_DATA_FROM_MODULE from there (python/CMakeLists.txt).
  Dl_info info{};
  std::string installed;
  if (::dladdr(reinterpret_cast<void*>(&shippedScenes), &info) != 0 && info.dli_fname) {
    installed = (std::filesystem::path(info.dli_fname).parent_path() / TABLETOP_DATA_FROM_MODULE)
                    .lexically_normal()
                    .string();
  }
  return dataFolder(installed, TABLETOP_SOURCE_DIR) + "/scenarios";
}

// A scene built from Python objects: the same format as a file, checked by
// the same loader, its problems located in the text it was written to.
Scenario scenarioOf(const py::object& scene) {
  if (py::isinstance<Scenario>(scene)) return scene.cast<Scenario>();
  if (py::isinstance<py::str>(scene)) return loadPath(scene.cast<std::string>());
  if (py::hasattr(scene, "__fspath__")) return loadPath(py::str(scene.attr("__fspath__")()).cast<std::string>());
  const std::string text = py::module_::import("json").attr("dumps")(scene, py::arg("indent") = 1).cast<std::string>();
  return ScenarioLoader::loadText(text, "<scene>");
}

py::object fromJson(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

}  // namespace tabletop::python
