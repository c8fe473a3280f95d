// A tabletop.Simulation's saved states. The simulation is deterministic, so
// a state is saved as how it was reached: the scene's origin (its text, mode
// and settings) and the calls made since it was built (SceneHistory).
// set_state(), copy() and unpickling build the scene again and make those
// calls: the state comes back bit for bit, checked by its state_hash. The
// cost is that of the steps replayed.
#include <cmath>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "core/StateHash.h"
#include "python/Arguments.h"
#include "python/Bindings.h"
#include "python/SignalCheck.h"
#include "scenario/JsonText.h"
#include "scenario/ScenarioLoader.h"

namespace tabletop::python {
namespace {

/// What get_state() returns: how the state was reached, and what it was.
struct SavedState {
  py::tuple origin;
  SceneHistory history;
  std::string hash;
  double time = 0.0;
  long steps = 0;
  std::vector<BodyMotion> motions;
};

constexpr int kMotionNumbers = 13;  // position 3, orientation 4, velocity 3, spin 3

std::string hashOf(const SteppedScene& scene) { return formatHash(stateHash(scene.simulation().snapshot())); }

SceneHistory historyFrom(const std::string& text) {
  const JsonText parsed = parseJsonText(text, "<history>", SceneHistory::kMaxJsonBytes, 8);
  return SceneHistory::fromJson(parsed.root);
}

// Builds the scene again and makes `history`'s calls on it, with the GIL
// released and Ctrl-C seen between steps; then checks the state reached.
void replay(SteppedScene& scene, const SceneHistory& history, const std::string& hash, const char* what) {
  {
    SignalCheck check;
    const py::gil_scoped_release nogil;
    scene.restore(history, std::ref(check));
  }
  if (!hash.empty() && hashOf(scene) != hash) {
    throw std::runtime_error(std::string(what) +
                             ": the calls that reached the state gave another one here (altered, or saved by "
                             "another build of tabletop)");
  }
}

// Builds `self` (made by __new__) as `origin` says the constructor was
// called, and brings it to the state `history` reaches.
void restoreInto(const py::handle& self, const py::tuple& origin, const SceneHistory& history, const std::string& hash) {
  if (origin.size() != 7 || !py::isinstance<py::str>(origin[0]) || !py::isinstance<py::str>(origin[1]) ||
      !py::isinstance<py::str>(origin[2]) || !py::isinstance<py::bool_>(origin[3])) {
    throw py::value_error("Simulation: expected a scene's origin (text, file, mode, script, timestep, iterations, "
                          "integrator)");
  }
  Scenario scenario = ScenarioLoader::loadText(origin[0].cast<std::string>(), origin[1].cast<std::string>());
  initialise(self, py::cast(std::move(scenario)), origin[2].cast<std::string>(), origin[3].cast<bool>(),
             origin[4].cast<std::optional<double>>(), origin[5], origin[6].cast<std::optional<std::string>>(),
             py::none());
  with(self, [&](SteppedScene& scene) { replay(scene, history, hash, "Simulation"); });
}

const py::tuple& picklable(SimulationObject& object) {
  if (object.origin()[0].is_none()) throw py::type_error("Simulation: a scene built in code cannot be copied");
  return object.origin();
}

py::object copied(const py::handle& self) {
  SimulationObject& object = initialised(self);
  const py::tuple& origin = picklable(object);
  const SavedState state = with(self, [&](SteppedScene& scene) {
    const std::string why = scene.unsaveable();
    if (!why.empty()) throw std::runtime_error("Simulation: cannot be copied: " + why);
    return SavedState{origin, scene.history(), hashOf(scene), 0.0, 0, {}};
  });
  py::object copy = py::type::of<SimulationObject>().attr("__new__")(py::type::of<SimulationObject>());
  restoreInto(copy, origin, state.history, state.hash);
  return copy;
}

py::array_t<double> stateRows(const SavedState& s, Motion part) { return motionRows(s.motions, part); }

void bindState(py::class_<SimulationObject>& simulation) {
  py::class_<SavedState>(simulation, "State",
                         "A Simulation's state as get_state() saved it: set_state() brings it back bit for bit. "
                         "It holds how the state was reached (the scene and the calls made), so it can be pickled.")
      .def_readonly("time", &SavedState::time, "Simulated seconds.")
      .def_readonly("steps", &SavedState::steps, "Steps taken.")
      .def_readonly("state_hash", &SavedState::hash, "The state's hash, as run --json gives it.")
      .def_property_readonly("positions", [](const SavedState& s) { return stateRows(s, Motion::Position); },
                             "Centres, m, shape (n, 3); read-only.")
      .def_property_readonly("orientations", [](const SavedState& s) { return stateRows(s, Motion::Orientation); },
                             "Unit quaternions w, x, y, z, shape (n, 4); read-only.")
      .def_property_readonly("velocities", [](const SavedState& s) { return stateRows(s, Motion::Velocity); },
                             "Linear velocities, m/s, shape (n, 3); read-only.")
      .def_property_readonly("angular_velocities", [](const SavedState& s) { return stateRows(s, Motion::Spin); },
                             "Angular velocities, rad/s, shape (n, 3); read-only.")
      .def("__repr__",
           [](const SavedState& s) {
             return "<tabletop.Simulation.State time=" + ranges::number(s.time) + " s steps=" +
                    std::to_string(s.steps) + " state_hash=" + s.hash + ">";
           })
      .def(py::pickle(
          [](const SavedState& s) {
            std::vector<double> numbers;
            for (const BodyMotion& b : s.motions) {
              numbers.insert(numbers.end(), {b.position.x, b.position.y, b.position.z});
              numbers.insert(numbers.end(), b.orientation.begin(), b.orientation.end());
              numbers.insert(numbers.end(), {b.linearVelocity.x, b.linearVelocity.y, b.linearVelocity.z});
              numbers.insert(numbers.end(), {b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z});
            }
            return py::make_tuple(s.origin, s.history.toJson().dump(), s.hash, s.time, s.steps, numbers);
          },
          [](const py::tuple& t) {
            if (t.size() != 6) throw py::value_error("State: expected a pickled tabletop state");
            SavedState s;
            s.origin = t[0].cast<py::tuple>();
            s.history = historyFrom(t[1].cast<std::string>());
            s.hash = t[2].cast<std::string>();
            s.time = t[3].cast<double>();
            s.steps = t[4].cast<long>();
            const auto numbers = t[5].cast<std::vector<double>>();
            if (numbers.size() % kMotionNumbers != 0 || numbers.size() > kMotionNumbers * ScenarioLoader::kMaxEntities) {
              throw py::value_error("State: expected 13 numbers a body");
            }
            for (std::size_t i = 0; i < numbers.size(); i += kMotionNumbers) {
              const double* n = &numbers[i];
              s.motions.push_back({{n[0], n[1], n[2]}, {n[3], n[4], n[5], n[6]}, {n[7], n[8], n[9]}, {n[10], n[11], n[12]}});
            }
            return s;
          }));
}

}  // namespace

void bindSimulationStates(py::class_<SimulationObject>& simulation) {
  bindState(simulation);
  simulation
      .def("reset", [](const py::handle& self) { with(self, [](SteppedScene& scene) { scene.reset(); }); },
           "Back to the state the scene was built in (bit for bit: the same state_hash).")
      .def(
          "get_state",
          [](const py::handle& self) {
            SimulationObject& object = initialised(self);
            return with(self, [&](SteppedScene& scene) {
              const std::string why = scene.unsaveable();
              if (!why.empty()) throw std::runtime_error("get_state: " + why);
              const Simulation& sim = scene.simulation();
              return SavedState{object.origin(), scene.history(), hashOf(scene), sim.time(), sim.steps(), sim.motions()};
            });
          },
          "The state now, as a Simulation.State: positions, orientations, velocities and spins, and how it was "
          "reached, so that set_state() gives it back bit for bit. RuntimeError after a step that raised.")
      .def(
          "set_state",
          [](const py::handle& self, const SavedState& state) {
            SimulationObject& object = initialised(self);
            if (!state.origin.equal(object.origin())) {
              throw py::value_error("set_state: the state is of another scene, mode or settings");
            }
            with(self, [&](SteppedScene& scene) { replay(scene, state.history, state.hash, "set_state"); });
          },
          py::arg("state"),
          "Brings back a state get_state() saved from this scene (same scene, mode and settings, else "
          "ValueError): the scene is built again and the calls that reached the state are made again, so the "
          "state is bit for bit the same; it costs the steps replayed. Ctrl-C stops it between steps.")
      .def("copy", &copied, "A new Simulation in the same state, bit for bit (the calls made on this one are made "
                            "again on a fresh build of the scene).")
      .def("__copy__", &copied, "copy.copy(sim): as copy().")
      .def(
          "__deepcopy__", [](const py::handle& self, const py::handle&) { return copied(self); }, py::arg("memo"),
          "copy.deepcopy(sim): as copy(); a Simulation shares nothing with its copy.")
      .def("__getstate__",
           [](const py::handle& self) {
             SimulationObject& object = initialised(self);
             const py::tuple& origin = picklable(object);
             return with(self, [&](SteppedScene& scene) {
               const std::string why = scene.unsaveable();
               if (!why.empty()) throw std::runtime_error("Simulation: cannot be pickled: " + why);
               return py::make_tuple(origin, scene.history().toJson().dump(), hashOf(scene));
             });
           },
           "For pickle: the scene's origin, the calls made since it was built, and the state's hash.")
      .def("__setstate__", [](const py::handle& self, const py::tuple& saved) {
        if (saved.size() != 3 || !py::isinstance<py::tuple>(saved[0]) || !py::isinstance<py::str>(saved[1]) ||
            !py::isinstance<py::str>(saved[2])) {
          throw py::value_error("Simulation: expected a pickled tabletop simulation");
        }
        restoreInto(self, saved[0].cast<py::tuple>(), historyFrom(saved[1].cast<std::string>()),
                    saved[2].cast<std::string>());
      }, "For pickle: builds the scene again and makes the calls; the state must come back to its hash.");
}

}  // namespace tabletop::python
