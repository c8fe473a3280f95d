// tabletop.Simulation: a scene stepped from Python. Every method checks its
// arguments before anything changes (Arguments.h), runs on the object's
// scene one thread at a time (SimulationObject), and steps and draws with
// the GIL released, looking for Ctrl-C between steps (SignalCheck).
#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/DirectionDef.h"
#include "core/Settings.h"
#include "core/Text.h"
#include "python/Arguments.h"
#include "python/Bindings.h"
#include "python/SignalCheck.h"
#include "python/SimulationObject.h"
#include "scenario/ScenarioLoader.h"
#include "sim/ResultFormat.h"

namespace tabletop::python {
namespace {

// Simulation(scene, ...): builds the scene and sets it into `self`. Written
// as a plain method named __init__, not pybind11's py::init: pybind11
// silently ignores a second __init__ on a live object, which would keep the
// old scene where the caller asked for a new one; here it is refused.
}  // namespace

void initialise(const py::handle& self, const py::object& scene, const std::string& mode, bool script,
                std::optional<double> timestep, const py::object& iterations, std::optional<std::string> integrator,
                const py::object& threads) {
  py::detail::value_and_holder holder = valueAndHolder(self);
  if (holder.holder_constructed()) {
    throw std::runtime_error("Simulation: already initialised; make a new Simulation for another scene");
  }
  Scenario scenario = resolved(scenarioOf(scene), {timestep, iterations, integrator, std::nullopt, threads});
  const SimulationMode chosen = modeNamed(mode);
  std::unique_ptr<SteppedScene> built;
  {
    const py::gil_scoped_release nogil;
    built = std::make_unique<SteppedScene>(std::move(scenario), chosen, script);
  }
  // Another thread may have initialised it while this one built without
  // the GIL; the check and the setting below happen under the GIL.
  if (holder.holder_constructed()) {
    throw std::runtime_error("Simulation: already initialised; make a new Simulation for another scene");
  }
  const auto& text = built->scenario().text;
  py::tuple origin = py::make_tuple(text ? py::object(py::str(*text)) : py::object(py::none()),
                                    built->scenario().file, mode, script, timestep, iterations, integrator);
  holder.value_ptr() = new SimulationObject(std::move(built), std::move(origin));
  holder.type->init_instance(holder.inst, nullptr);  // the holder owns it from here, as py::init's would
}

namespace {

void step(const py::handle& self, const py::object& n) {
  with(self, [&](SteppedScene& scene) {
    const long long count = checkedInteger("step: n", n, 0, static_cast<long long>(kMaxSteps));
    const std::string tooMuch = ScenarioLoader::workProblem(static_cast<double>(count), scene.scenario().settings,
                                                            scene.scenario().entities.size());
    if (!tooMuch.empty()) throw py::value_error("step: n: " + tooMuch);
    SignalCheck check;
    const py::gil_scoped_release nogil;
    scene.step(count, std::ref(check));
  });
}

void runToEnd(const py::handle& self) {
  with(self, [](SteppedScene& scene) {
    SignalCheck check;
    const py::gil_scoped_release nogil;
    scene.runToEnd(std::ref(check));
  });
}

// A push by impulse or by step, at an angle or on a face: the loader's
// script push, its fields named as the arguments. An impulse given as a
// vector, or at a point, is applied as it is (Simulation::applyImpulse).
void push(const py::handle& self, const py::object& entity, const py::object& impulse, std::optional<double> step,
          std::optional<double> angle, std::optional<std::string> face, const py::object& point) {
  with(self, [&](SteppedScene& scene) {
    const std::string& name = checkedEntity("push: entity", scene.scenario(), entity);
    if (impulse.is_none() == !step.has_value()) throw py::value_error("push: expected exactly one of 'step', 'impulse'");
    if (face && angle) throw py::value_error("push: expected at most one of 'face', 'angle'");
    const bool vector = !impulse.is_none() && PySequence_Check(impulse.ptr());
    if (vector || !point.is_none()) {
      if (!vector) throw py::value_error("push: point: expected the impulse as a vector [x, y, z] with it");
      if (face || angle) throw py::value_error("push: an impulse given as a vector takes no 'face' or 'angle'");
      const Vec3 j = checkedVector("push: impulse", impulse, ranges::kImpulseComponent);
      std::optional<Vec3> at;
      if (!point.is_none()) at = checkedVector("push: point", point, ranges::kCoordinate);
      scene.applyImpulse(name, j, at);
      return;
    }
    Arrow arrow;
    arrow.entity = name;
    if (face) {
      arrow.face = directionFromString(*face);
      if (!arrow.face) {
        throw py::value_error("push: face: expected one of Left, Right, Front, Back, got \"" + shownText(*face, 40) +
                              "\"");
      }
    } else {
      arrow.angleDegrees = angle ? checkedNumber("push: angle", *angle, ranges::kAngle) : 0.0;
    }
    const PushMagnitude magnitude =
        !impulse.is_none()
            ? PushMagnitude{PushMagnitude::Kind::Impulse,
                            checkedNumber("push: impulse", py::float_(impulse).cast<double>(), ranges::kImpulse)}
            : PushMagnitude{PushMagnitude::Kind::Step, checkedNumber("push: step", *step, ranges::kStep)};
    scene.push(arrow, magnitude);
  });
}

// A force and a torque held through the next step (PyBullet's
// applyExternalForce and applyExternalTorque).
void applyForce(const py::handle& self, const py::object& entity, const py::object& force, const py::object& torque,
                const py::object& point, const char* what) {
  with(self, [&](SteppedScene& scene) {
    const std::string& name = checkedEntity(std::string(what) + ": entity", scene.scenario(), entity);
    const Vec3 f = force.is_none() ? Vec3{} : checkedVector(std::string(what) + ": force", force, ranges::kForceComponent);
    const Vec3 t = torque.is_none() ? Vec3{} : checkedVector(std::string(what) + ": torque", torque, ranges::kForceComponent);
    std::optional<Vec3> at;
    if (!point.is_none()) at = checkedVector(std::string(what) + ": point", point, ranges::kCoordinate);
    scene.applyForce(name, f, t, at);
  });
}

void rotate(const py::handle& self, const py::object& entity, double degrees) {
  with(self, [&](SteppedScene& scene) {
    const std::string& name = checkedEntity("rotate: entity", scene.scenario(), entity);
    scene.rotate(name, checkedNumber("rotate: degrees", degrees, ranges::kAngle));
  });
}

// The RGB frame alone, or with depth and segmentation images: a tuple of
// what was asked for, in that order.
py::object render(const py::handle& self, const py::object& width, const py::object& height, const std::string& camera,
                  bool arrow, bool depth, bool segmentation) {
  return with(self, [&](SteppedScene& scene) {
    const int w = static_cast<int>(checkedInteger("render: width", width, 1, kMaxImageSide));
    const int h = static_cast<int>(checkedInteger("render: height", height, 1, kMaxImageSide));
    // "fit:now" is "fit" framing the scene as it is now, not its run.
    const bool now = camera == "fit:now";
    const auto chosen = CameraChoice::forScene(now ? "fit" : camera, scene.scenario());
    if (const auto* why = std::get_if<std::string>(&chosen)) throw py::value_error("render: camera: " + *why);
    Image image;
    BodyImage bodies;
    const bool more = depth || segmentation;
    {
      const py::gil_scoped_release nogil;
      image = scene.render(w, h, std::get<CameraChoice>(chosen), arrow, now, more ? &bodies : nullptr);
    }
    py::array_t<std::uint8_t> rgb({h, w, 3});
    std::copy(image.rgb.begin(), image.rgb.end(), rgb.mutable_data());
    if (!more) return py::object(rgb);
    py::list out;
    out.append(rgb);
    if (depth) {
      py::array_t<float> d({h, w});
      std::copy(bodies.depth.begin(), bodies.depth.end(), d.mutable_data());
      out.append(d);
    }
    if (segmentation) {
      py::array_t<std::int32_t> s({h, w});
      std::copy(bodies.labels.begin(), bodies.labels.end(), s.mutable_data());
      out.append(s);
    }
    return py::object(py::tuple(out));
  });
}

}  // namespace

void bindSimulation(py::module_& m) {
  py::class_<SimulationObject> simulation(
      m, "Simulation",
      "A scenario stepped from Python in one mode. Arrays have one row per entity, in the scenario's order. One "
      "call at a time uses it (another thread's call waits); stepping and drawing release the GIL; close() frees "
      "it (or use it in a with block).");
  simulation.attr("__init__") = py::cpp_function(
      &initialise, py::is_method(simulation), py::arg("scene"), py::kw_only(),
      py::arg("mode") = "bullet", py::arg("script") = true, py::arg("timestep") = py::none(),
      py::arg("iterations") = py::none(), py::arg("integrator") = py::none(), py::arg("threads") = py::none(),
      "Builds the scene (a Scenario, a file's path or a shipped scene's name, or a scene's objects) in mode "
      "'bullet', 'compat' or 'rules'. With script True its script is carried out as time "
      "passes; with False only the pushes given from Python happen. timestep, iterations and integrator override "
      "the scenario's, within its limits; threads (1 to 256; None: TABLETOP_THREADS, else every core) share out the "
      "independent islands and give the same states to the bit, and a copy or a pickle takes the default again. "
      "A second __init__ on a live Simulation raises RuntimeError.");
  simulation
      .def("step", &step, py::arg("n") = 1,
           "Advances n fixed timesteps (carrying out the script's actions as they fall due): n from 0 to 1e7, and "
           "at most 1e11 solver work (n x max_substeps x iterations x entities), as a scenario's run; while it "
           "runs, at most 6e11 units of work (docs/limits.md), else ScenarioError. Raises DivergenceError if a body leaves the scene's bounds; Ctrl-C stops it between steps.")
      .def("run_to_end", &runToEnd,
           "Steps until the scenario's duration is reached, or its script is done and everything rests. Ctrl-C "
           "stops it between steps.")
      .def("push", &push, py::arg("entity"), py::kw_only(), py::arg("impulse") = py::none(),
           py::arg("step") = py::none(), py::arg("angle") = py::none(), py::arg("face") = py::none(),
           py::arg("point") = py::none(),
           "Pushes an entity (its name or index) now by an impulse (N s, up to 1e6) or by a step (m, up to 100: "
           "the impulse that makes it, alone on the table, travel that far), at a world angle in degrees (0 is +X, "
           "90 is -Z; the default) or on a face (Front, Back, Left, Right): the report's push. An impulse given as "
           "a vector [x, y, z] (N s, each part within +-1e6) is applied as it is, through the centre of mass or "
           "at point [x, y, z] (m, world frame), which sets the body spinning: the velocity changes by J/m and "
           "the spin by I^-1 (r x J). Modes 'compat' and 'rules' take only a horizontal vector through the "
           "centre (ValueError otherwise).")
      .def(
          "apply_force",
          [](const py::handle& self, const py::object& entity, const py::object& force, const py::object& point) {
            applyForce(self, entity, force, py::none(), point, "apply_force");
          },
          py::arg("entity"), py::arg("force"), py::kw_only(), py::arg("point") = py::none(),
          "Applies a force [x, y, z] (N, each part within +-1e7) to an entity (its name or index) through the next "
          "step only, as PyBullet's applyExternalForce: through the centre of mass, or at point [x, y, z] (m, world "
          "frame), which adds its moment r x F. Forces given before a step add up. Mode 'bullet' only "
          "(ValueError in 'compat' and 'rules', which move bodies by pushes).")
      .def(
          "apply_torque",
          [](const py::handle& self, const py::object& entity, const py::object& torque) {
            applyForce(self, entity, py::none(), torque, py::none(), "apply_torque");
          },
          py::arg("entity"), py::arg("torque"),
          "Applies a torque [x, y, z] (N m, world frame, each part within +-1e7) to an entity through the next step "
          "only. Mode 'bullet' only.")
      .def("rotate", &rotate, py::arg("entity"), py::arg("degrees"),
           "Turns an entity (its name or index) about its own vertical axis (the report's Rotate), degrees within "
           "+-1e6.")
      .def("render", &render, py::arg("width") = 640, py::arg("height") = 480, py::kw_only(),
           py::arg("camera") = "fit", py::arg("arrow") = true, py::arg("depth") = false,
           py::arg("segmentation") = false,
           "The scene now, drawn headless (OSMesa) and anti-aliased, as a NumPy array of shape (height, width, 3), "
           "uint8 RGB, top row first; each side 1 to 8192 pixels. camera is render's --camera, with the same "
           "meaning: fit (the default: the table and all the scene's run reaches, its script played from the start "
           "to its end, found once by running a copy, and the scene now; frames in a loop keep this camera), "
           "front, corner, side, top, follow:NAME or 'EX,EY,EZ:TX,TY,TZ'; and fit:now, the scene as it is now. With "
           "depth or segmentation, a tuple: the RGB frame, then each asked for, as PyBullet's getCameraImage: depth, "
           "float32 (height, width), metres from the camera along its view axis (inf where nothing is); "
           "segmentation, int32 (height, width), each pixel's body: the entity's index in the arrays, -2 the table, "
           "-3 the ground, -1 nothing.")
      .def("close", [](const py::handle& self) { initialised(self).close(); },
           "Frees the scene (waiting for a call running in another thread); every later call but close() raises "
           "RuntimeError.")
      .def("__enter__", [](const py::object& self) { return self; })
      .def("__exit__", [](const py::handle& self, const py::args&) { initialised(self).close(); })
      .def_property_readonly("closed", [](const py::handle& self) { return initialised(self).closed(); },
                             "True once close() was called.");
  bindSimulationReadings(simulation);
  bindSimulationStates(simulation);
}

}  // namespace tabletop::python
