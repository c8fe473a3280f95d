// tabletop.Scenario, load, scene, run and shipped_scenes, and the
// exceptions every part of the module raises: a scenario refused (with the
// command line's located lines), a run that diverged, and a Python error
// already set (Ctrl-C).
#include <memory>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "python/Arguments.h"
#include "python/Bindings.h"
#include "python/SignalCheck.h"
#include "scenario/ScenarioError.h"
#include "scenario/ShippedScenes.h"
#include "sim/DivergenceGuard.h"
#include "sim/ResultFormat.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"

namespace tabletop::python {
namespace {

std::string joinedLines(const ScenarioError& e) {
  std::string text;
  for (const std::string& line : e.lines()) text += (text.empty() ? "" : "\n") + line;
  return text;
}

// run(): the whole run with the GIL released, Ctrl-C looked for between
// steps; bounded by the duration, which resolved() bounded.
py::object run(const py::object& scene, const std::string& mode, std::optional<double> timestep,
               const py::object& iterations, std::optional<std::string> integrator, std::optional<double> duration,
               const py::object& threads) {
  const Scenario scenario = resolved(scenarioOf(scene), {timestep, iterations, integrator, duration, threads});
  const SimulationMode chosen = modeNamed(mode);
  RunResult result;
  {
    const py::gil_scoped_release nogil;
    const std::unique_ptr<Simulation> simulation = buildSimulation(scenario, scenario.settings, chosen);
    SignalCheck check;
    result = runScript(scenario, scenario.settings, *simulation, [&check](const Simulation&) { check(); });
  }
  return fromJson(toJson(result));
}

// shipped_scenes(): the list `tabletop list --json` prints.
py::list shippedSceneList() {
  py::list scenes;
  for (const ShippedScene& s : listShippedScenes(shippedScenes())) {
    py::dict scene;
    scene["name"] = s.name;
    scene["description"] = s.description;
    scene["file"] = s.file;
    scene["loads"] = s.loads;
    scenes.append(scene);
  }
  return scenes;
}

}  // namespace

std::vector<std::string> entityNames(const Scenario& scenario) {
  std::vector<std::string> names;
  for (const EntitySpec& e : scenario.entities) names.push_back(e.name);
  return names;
}

void bindScenarios(py::module_& m) {
  static py::exception<ScenarioError> scenarioError(m, "ScenarioError", PyExc_ValueError);
  scenarioError.doc() =
      "A scenario that cannot be run: one line per problem, FILE:LINE:COL: at /pointer: message, as the command "
      "line prints it.";
  static py::exception<DivergenceError> divergenceError(m, "DivergenceError", PyExc_RuntimeError);
  divergenceError.doc() = "A run that left the bounds of its scene (a body too fast, or through the floor).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ScenarioError& e) {
      scenarioError(joinedLines(e).c_str());
    } catch (const DivergenceError& e) {
      divergenceError(e.what());
    } catch (const PythonErrorSet&) {
      // The error a signal handler raised (KeyboardInterrupt) is already set.
    }
  });

  py::class_<Scenario>(m, "Scenario", "A scene and its script, as loaded and checked from a file or from objects.")
      .def_readonly("name", &Scenario::name, "The scenario's name.")
      .def_readonly("file", &Scenario::file, "Where it was read from ('<scene>' for one built from objects).")
      .def_property_readonly("entities", &entityNames, "The entities' names, in the order every array gives them.");

  m.def("load", &loadPath, py::arg("path"),
        "Reads and checks a scenario file (JSON with comments; the format of scenarios/README.md), or, where no "
        "file has that path, the shipped scene of that name ('example2_two_cubes', 'hard/pyramid_55'; "
        "shipped_scenes() names them). Raises ScenarioError with every problem located.");
  m.def("shipped_scenes", &shippedSceneList,
        "The scenes shipped with tabletop, as `tabletop list --json` gives them: a dict each, with the name load, "
        "run and Simulation take from any folder, its description, its file, and whether it loads.");
  m.def(
      "scene", [](const py::object& object) { return scenarioOf(object); }, py::arg("scene"),
      "Builds a scenario from Python objects (dicts, lists, numbers, strings) in the scenario file's format, "
      "checked as a file is; problems are located in that object written as JSON.");
  m.def("run", &run, py::arg("scene"), py::kw_only(), py::arg("mode") = "bullet", py::arg("timestep") = py::none(),
        py::arg("iterations") = py::none(), py::arg("integrator") = py::none(), py::arg("duration") = py::none(),
        py::arg("threads") = py::none(),
        "Runs a scenario (a Scenario, a file's path or a shipped scene's name, or a scene's objects) to its end and returns its run as "
        "`tabletop run --json` prints it (one entry of the document's runs): entities, events, state_hash, "
        "complete. A run that diverges returns complete False with its failure. The keyword settings override the "
        "scenario's, as run's options do, within the same limits; threads (1 to 256; None: TABLETOP_THREADS, else "
        "every core) share out the independent islands and give the same run to the bit. The GIL is released while it runs; Ctrl-C stops "
        "it.");
}

}  // namespace tabletop::python
