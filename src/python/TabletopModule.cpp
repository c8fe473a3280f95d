// `import tabletop`: scenarios loaded from files or built from Python
// objects, run whole (the run `tabletop run --json` prints) or stepped
// from Python in any of the three modes, their state as NumPy arrays, and
// frames rendered headless into NumPy images. Errors are Python
// exceptions carrying the command line's located messages.
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "draw/CameraChoice.h"
#include "draw/SceneDrawing.h"
#include "headless/HeadlessFrames.h"
#include "python/SweepBinding.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "sim/DivergenceGuard.h"
#include "sim/ResultFormat.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptPlayer.h"
#include "sim/ScriptRunner.h"

namespace py = pybind11;

namespace tabletop {
namespace {

// What the Python side may override of a scenario's settings, as `run`'s
// options do; checked against the loader's limits on the run's size.
struct Overrides {
  std::optional<double> timestep;
  std::optional<int> iterations;
  std::optional<std::string> integrator;
  std::optional<double> duration;
};

Scenario resolved(Scenario scenario, const Overrides& o) {
  Settings& s = scenario.settings;
  if (o.timestep) s.timestep = *o.timestep;
  if (o.iterations) s.iterations = *o.iterations;
  if (o.integrator) {
    const auto integrator = integratorFromString(*o.integrator);
    if (!integrator) throw py::value_error("integrator: expected trapezoid or euler, got '" + *o.integrator + "'");
    s.integrator = *integrator;
  }
  if (o.duration) s.duration = *o.duration;
  const std::string problem = ScenarioLoader::runSizeProblem(s, scenario.entities.size());
  if (!problem.empty() || !(s.timestep > 0.0) || s.iterations < 1 || !(s.duration > 0.0)) {
    throw ScenarioError(scenario, {{"/settings", (problem.empty() ? "expected a positive timestep, iterations and "
                                                                     "duration"
                                                                   : problem) +
                                                     " with the settings given from Python"}});
  }
  return scenario;
}

SimulationMode modeNamed(const std::string& name) {
  const auto mode = simulationModeFromString(name);
  if (!mode) throw py::value_error("mode: expected bullet, compat or rules, got '" + name + "'");
  return *mode;
}

py::object fromJson(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

// A scene built from Python objects: the same format as a file, checked by
// the same loader, its problems located in the text it was written to.
Scenario sceneFromObject(const py::object& object, const std::string& source) {
  const std::string text = py::module_::import("json").attr("dumps")(object, py::arg("indent") = 1).cast<std::string>();
  return ScenarioLoader::loadText(text, source);
}

Scenario scenarioOf(const py::object& scene) {
  if (py::isinstance<Scenario>(scene)) return scene.cast<Scenario>();
  if (py::isinstance<py::str>(scene)) return ScenarioLoader::loadFile(scene.cast<std::string>());
  if (py::hasattr(scene, "__fspath__")) return ScenarioLoader::loadFile(py::str(scene.attr("__fspath__")()));
  return sceneFromObject(scene, "<scene>");
}

// A scene stepped from Python: the scenario it owns, the simulation in
// one mode, and the script player that carries out its script (none when
// asked for) and guards against divergence.
class Stepper {
 public:
  Stepper(Scenario scenario, SimulationMode mode, bool script)
      : scenario_(std::make_unique<Scenario>(std::move(scenario))) {
    if (!script) scenario_->script.clear();
    simulation_ = buildSimulation(*scenario_, scenario_->settings, mode);
    player_ = std::make_unique<ScriptPlayer>(*scenario_, scenario_->settings, *simulation_);
    player_->runDue();
  }

  void step(long n) {
    for (long k = 0; k < n; ++k) player_->step();
  }
  void runToEnd() { player_->runToEnd(); }

  void push(const std::string& entity, std::optional<double> impulse, std::optional<double> step,
            std::optional<double> angle, std::optional<std::string> face) {
    if (impulse.has_value() == step.has_value()) throw py::value_error("push: give either impulse (N s) or step (m)");
    Arrow arrow;
    arrow.entity = entity;
    if (face) {
      arrow.face = directionFromString(*face);
      if (!arrow.face) throw py::value_error("push: face: expected Front, Back, Left or Right, got '" + *face + "'");
    } else {
      arrow.angleDegrees = angle.value_or(0.0);
    }
    const PushMagnitude magnitude{impulse ? PushMagnitude::Kind::Impulse : PushMagnitude::Kind::Step,
                                  impulse ? *impulse : *step};
    player_->push(arrow, magnitude);
  }

  void rotate(const std::string& entity, double degrees) { simulation_->rotate(entity, degrees); }

  // One row per entity, in scenario order.
  template <typename Pick>
  py::array_t<double> rows(int columns, Pick pick) const {
    const std::vector<BodyMotion> motions = simulation_->motions();
    py::array_t<double> out({static_cast<py::ssize_t>(motions.size()), static_cast<py::ssize_t>(columns)});
    auto view = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < motions.size(); ++i) {
      const std::vector<double> row = pick(motions[i]);
      for (int c = 0; c < columns; ++c) view(static_cast<py::ssize_t>(i), c) = row[static_cast<std::size_t>(c)];
    }
    return out;
  }

  RunResult result() const { return outcomeNow(*scenario_, scenario_->settings, *simulation_); }

  py::array_t<std::uint8_t> render(int width, int height, const std::string& cameraName, bool arrow) const {
    if (width < 1 || height < 1 || width > 8192 || height > 8192) {
      throw py::value_error("render: expected a width and height from 1 to 8192 pixels");
    }
    const auto chosen = CameraChoice::forScene(cameraName, *scenario_);
    if (const auto* why = std::get_if<std::string>(&chosen)) throw py::value_error("render: camera: " + *why);
    const CameraChoice& choice = std::get<CameraChoice>(chosen);
    const std::vector<EntityState> states = simulation_->snapshot();
    const HeadlessFrames frames(width, height);
    DrawOptions options;
    options.arrow = arrow;
    const Image image = frames.draw(makeDrawList(*scenario_, states, player_->arrow(), {}, options),
                                    cameraFor(choice, *scenario_, states, SceneExtent::of(*scenario_, states),
                                              double(width) / height));
    py::array_t<std::uint8_t> out({height, width, 3});
    std::copy(image.rgb.begin(), image.rgb.end(), out.mutable_data());
    return out;
  }

  const Scenario& scenario() const { return *scenario_; }
  const Simulation& simulation() const { return *simulation_; }
  bool finished() const { return player_->finished(); }

 private:
  std::unique_ptr<Scenario> scenario_;
  std::unique_ptr<Simulation> simulation_;
  std::unique_ptr<ScriptPlayer> player_;
};

std::vector<std::string> entityNames(const Scenario& scenario) {
  std::vector<std::string> names;
  for (const EntitySpec& e : scenario.entities) names.push_back(e.name);
  return names;
}

std::string joinedLines(const ScenarioError& e) {
  std::string text;
  for (const std::string& line : e.lines()) text += (text.empty() ? "" : "\n") + line;
  return text;
}

}  // namespace
}  // namespace tabletop

PYBIND11_MODULE(tabletop, m) {
  using namespace tabletop;
  m.doc() =
      "tabletop: the table-top scenes of S. Zou's report \"The Design of a 3D-Object Simulator Using Open-GL\" "
      "(Concordia, 2001) simulated with Bullet rigid-body physics, in three modes: bullet (full physics), compat "
      "(Bullet held to the report's rules) and rules (the report's rules alone). SI units, Y up, angles in degrees.";

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
    }
  });

  m.attr("__version__") = TABLETOP_VERSION;
  addSweep(m);

  py::class_<Scenario>(m, "Scenario", "A scene and its script, as loaded and checked from a file or from objects.")
      .def_readonly("name", &Scenario::name, "The scenario's name.")
      .def_readonly("file", &Scenario::file, "Where it was read from ('<scene>' for one built from objects).")
      .def_property_readonly("entities", &entityNames, "The entities' names, in the order every array gives them.");

  m.def("load", [](const std::string& path) { return ScenarioLoader::loadFile(path); }, py::arg("path"),
        "Reads and checks a scenario file (JSON with comments; the format of scenarios/README.md). Raises "
        "ScenarioError with every problem located.");
  m.def(
      "scene", [](const py::object& object) { return sceneFromObject(object, "<scene>"); }, py::arg("scene"),
      "Builds a scenario from Python objects (dicts, lists, numbers, strings) in the scenario file's format, "
      "checked as a file is; problems are located in that object written as JSON.");

  m.def(
      "run",
      [](const py::object& scene, const std::string& mode, std::optional<double> timestep,
         std::optional<int> iterations, std::optional<std::string> integrator, std::optional<double> duration) {
        const Scenario scenario = resolved(scenarioOf(scene), {timestep, iterations, integrator, duration});
        const std::unique_ptr<Simulation> simulation = buildSimulation(scenario, scenario.settings, modeNamed(mode));
        return fromJson(toJson(runScript(scenario, scenario.settings, *simulation)));
      },
      py::arg("scene"), py::kw_only(), py::arg("mode") = "bullet", py::arg("timestep") = py::none(),
      py::arg("iterations") = py::none(), py::arg("integrator") = py::none(), py::arg("duration") = py::none(),
      "Runs a scenario (a Scenario, a file's path, or a scene's objects) to its end and returns its run as `tabletop "
      "run --json` prints it (one entry of the document's runs): entities, events, state_hash, complete. A run that diverges returns complete False with its "
      "failure. The keyword settings override the scenario's, as run's options do.");

  py::class_<Stepper>(m, "Simulation",
                      "A scenario stepped from Python in one mode. Arrays have one row per entity, in the "
                      "scenario's order.")
      .def(py::init([](const py::object& scene, const std::string& mode, bool script, std::optional<double> timestep,
                       std::optional<int> iterations, std::optional<std::string> integrator) {
             return std::make_unique<Stepper>(
                 resolved(scenarioOf(scene), {timestep, iterations, integrator, std::nullopt}), modeNamed(mode),
                 script);
           }),
           py::arg("scene"), py::kw_only(), py::arg("mode") = "bullet", py::arg("script") = true,
           py::arg("timestep") = py::none(), py::arg("iterations") = py::none(), py::arg("integrator") = py::none(),
           "Builds the scene in mode 'bullet', 'compat' or 'rules'. With script True its script is carried out as "
           "time passes; with False only the pushes given from Python happen.")
      .def("step", &Stepper::step, py::arg("n") = 1,
           "Advances n fixed timesteps (carrying out the script's actions as they fall due). Raises "
           "DivergenceError if a body leaves the scene's bounds.")
      .def("run_to_end", &Stepper::runToEnd,
           "Steps until the scenario's duration is reached, or its script is done and everything rests.")
      .def("push", &Stepper::push, py::arg("entity"), py::kw_only(), py::arg("impulse") = py::none(),
           py::arg("step") = py::none(), py::arg("angle") = py::none(), py::arg("face") = py::none(),
           "Pushes an entity now by an impulse (N s) or by a step (m: the impulse that makes it, alone on the "
           "table, travel that far), at a world angle in degrees (0 is +X, 90 is -Z) or on a face (Front, Back, "
           "Left, Right).")
      .def("rotate", &Stepper::rotate, py::arg("entity"), py::arg("degrees"),
           "Turns an entity about its own vertical axis (the report's Rotate).")
      .def("render", &Stepper::render, py::arg("width") = 640, py::arg("height") = 480, py::kw_only(),
           py::arg("camera") = "fit", py::arg("arrow") = true,
           "The scene now, drawn headless (OSMesa) and anti-aliased, as a NumPy array of shape (height, width, 3), "
           "uint8 RGB, top row first. camera is render's --camera: fit (the scene as it is now), front, corner, "
           "side, top, follow:NAME or 'EX,EY,EZ:TX,TY,TZ'.")
      .def_property_readonly(
          "positions", [](const Stepper& s) { return s.rows(3, [](const BodyMotion& b) { return std::vector<double>{b.position.x, b.position.y, b.position.z}; }); },
          "Centres, m, shape (n, 3).")
      .def_property_readonly(
          "orientations",
          [](const Stepper& s) {
            return s.rows(4, [](const BodyMotion& b) { return std::vector<double>(b.orientation.begin(), b.orientation.end()); });
          },
          "Unit quaternions w, x, y, z, shape (n, 4).")
      .def_property_readonly(
          "velocities",
          [](const Stepper& s) {
            return s.rows(3, [](const BodyMotion& b) {
              return std::vector<double>{b.linearVelocity.x, b.linearVelocity.y, b.linearVelocity.z};
            });
          },
          "Linear velocities, m/s, shape (n, 3).")
      .def_property_readonly(
          "angular_velocities",
          [](const Stepper& s) {
            return s.rows(3, [](const BodyMotion& b) {
              return std::vector<double>{b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z};
            });
          },
          "Angular velocities, rad/s, world frame, shape (n, 3).")
      .def_property_readonly("names", [](const Stepper& s) { return entityNames(s.scenario()); },
                             "The entities' names, in the arrays' order.")
      .def_property_readonly("time", [](const Stepper& s) { return s.simulation().time(); }, "Simulated seconds.")
      .def_property_readonly("steps", [](const Stepper& s) { return s.simulation().steps(); }, "Steps taken.")
      .def_property_readonly("timestep", [](const Stepper& s) { return s.scenario().settings.timestep; },
                             "The fixed timestep, s.")
      .def_property_readonly("at_rest", [](const Stepper& s) { return s.simulation().allAtRest(); },
                             "True when no entity moves.")
      .def_property_readonly("finished", &Stepper::finished,
                             "True once the duration is reached, or the script is done and all rests.")
      .def_property_readonly("mode", [](const Stepper& s) { return std::string(s.simulation().modeName()); },
                             "'bullet', 'compat' or 'rules'.")
      .def("result", [](const Stepper& s) { return fromJson(toJson(s.result())); },
           "The state now as run --json gives it: entities (position, orientation, velocities, status, "
           "support), events, state_hash.");
}
