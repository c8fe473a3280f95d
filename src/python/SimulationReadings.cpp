// What a tabletop.Simulation reads out: the state as arrays (fresh and
// read-only, so a write is an error, not a change silently lost), the
// contacts, the scene's facts, and a repr.
#include <cstdio>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "core/ContactReport.h"
#include "python/Arguments.h"
#include "python/Bindings.h"
#include "sim/ResultFormat.h"

namespace tabletop::python {
namespace {

std::vector<double> xyz(const Vec3& v) { return {v.x, v.y, v.z}; }
py::tuple tuple3(const Vec3& v) { return py::make_tuple(v.x, v.y, v.z); }

}  // namespace

py::array_t<double> motionRows(const std::vector<BodyMotion>& motions, Motion part) {
  const int columns = part == Motion::Orientation ? 4 : 3;
  py::array_t<double> out({static_cast<py::ssize_t>(motions.size()), static_cast<py::ssize_t>(columns)});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < motions.size(); ++i) {
    const BodyMotion& b = motions[i];
    std::vector<double> row;
    switch (part) {
      case Motion::Position: row = xyz(b.position); break;
      case Motion::Orientation: row.assign(b.orientation.begin(), b.orientation.end()); break;
      case Motion::Velocity: row = xyz(b.linearVelocity); break;
      case Motion::Spin: row = xyz(b.angularVelocity); break;
    }
    for (int c = 0; c < columns; ++c) view(static_cast<py::ssize_t>(i), c) = row[static_cast<std::size_t>(c)];
  }
  out.attr("flags").attr("writeable") = false;
  return out;
}

void bindMotionArrays(py::class_<SimulationObject>& simulation) {
  const auto rows = [](Motion part) {
    return [part](const py::handle& s) {
      return with(s, [&](SteppedScene& x) { return motionRows(x.simulation().motions(), part); });
    };
  };
  simulation
      .def_property_readonly("positions", rows(Motion::Position), "Centres, m, shape (n, 3); read-only.")
      .def_property_readonly("orientations", rows(Motion::Orientation),
                             "Unit quaternions w, x, y, z, shape (n, 4); read-only.")
      .def_property_readonly("velocities", rows(Motion::Velocity), "Linear velocities, m/s, shape (n, 3); read-only.")
      .def_property_readonly("angular_velocities", rows(Motion::Spin),
                             "Angular velocities, rad/s, world frame, shape (n, 3); read-only.");
}

void bindSimulationReadings(py::class_<SimulationObject>& simulation) {
  py::class_<ContactReport>(simulation, "Contact",
                            "Where two bodies touch after the last step (within 1 mm of touching).")
      .def_property_readonly("a", [](const ContactReport& c) { return c.a.name(); }, "An entity's name.")
      .def_property_readonly("b", [](const ContactReport& c) { return c.b.name(); },
                             "The other body: an entity's name, 'table' or 'ground'.")
      .def_property_readonly("point", [](const ContactReport& c) { return tuple3(c.point); },
                             "Midway between the two surfaces, m, world frame.")
      .def_property_readonly("normal", [](const ContactReport& c) { return tuple3(c.normal); },
                             "Unit normal from b towards a.")
      .def_readonly("depth", &ContactReport::depth, "How far the surfaces overlap, m; negative while a gap is left.")
      .def_readonly("impulse", &ContactReport::impulse, "The normal impulse of the step's last solve, N s.")
      .def("__repr__", [](const ContactReport& c) {
        char text[160];
        std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g) normal (%.6g, %.6g, %.6g) depth %.3g m impulse %.6g N s",
                      c.point.x, c.point.y, c.point.z, c.normal.x, c.normal.y, c.normal.z, c.depth, c.impulse);
        return "<Contact " + shownText(c.a.name(), 40) + " on " + shownText(c.b.name(), 40) + " at " + text + ">";
      });
  bindMotionArrays(simulation);
  simulation
      .def_property_readonly(
          "contacts", [](const py::handle& s) { return with(s, [](SteppedScene& x) { return x.simulation().contacts(); }); },
          "Where bodies touch after the last step, a list of Simulation.Contact (empty in mode 'rules', which has "
          "no contacts).")
      .def_property_readonly(
          "names", [](const py::handle& s) { return with(s, [](SteppedScene& x) { return entityNames(x.scenario()); }); },
          "The entities' names, in the arrays' order.")
      .def_property_readonly(
          "time", [](const py::handle& s) { return with(s, [](SteppedScene& x) { return x.simulation().time(); }); },
          "Simulated seconds.")
      .def_property_readonly(
          "steps", [](const py::handle& s) { return with(s, [](SteppedScene& x) { return x.simulation().steps(); }); },
          "Steps taken.")
      .def_property(
          "timestep",
          [](const py::handle& s) { return with(s, [](SteppedScene& x) { return x.scenario().settings.timestep; }); },
          [](const py::handle& s, double seconds) {
            checkedNumber("timestep", seconds, ranges::kTimestep);
            with(s, [&](SteppedScene& x) { x.setTimestep(seconds); });
          },
          "The fixed timestep, s; set between steps (1e-5 to 0.1 s), the steps after it take the new one.")
      .def_property(
          "gravity",
          [](const py::handle& s) { return with(s, [](SteppedScene& x) { return x.scenario().settings.gravity; }); },
          [](const py::handle& s, double g) {
            checkedNumber("gravity", g, ranges::kGravity);
            with(s, [&](SteppedScene& x) { x.setGravity(g); });
          },
          "Gravity, m/s^2 along -Y; set between steps (0 to 100), the steps after it fall under the new one.")
      .def_property_readonly(
          "at_rest", [](const py::handle& s) { return with(s, [](SteppedScene& x) { return x.simulation().allAtRest(); }); },
          "True when no entity moves.")
      .def_property_readonly(
          "finished", [](const py::handle& s) { return with(s, [](SteppedScene& x) { return x.finished(); }); },
          "True once the duration is reached, or the script is done and all rests.")
      .def_property_readonly(
          "mode",
          [](const py::handle& s) { return with(s, [](SteppedScene& x) { return std::string(x.simulation().modeName()); }); },
          "'bullet', 'compat' or 'rules'.")
      .def(
          "result", [](const py::handle& s) { return with(s, [](SteppedScene& x) { return fromJson(toJson(x.result())); }); },
          "The state now as run --json gives it: entities (position, orientation, velocities, status, support), "
          "events, state_hash.")
      .def("__repr__", [](const py::handle& s) -> std::string {
        if (!valueAndHolder(s).holder_constructed()) return "<tabletop.Simulation (not initialised)>";
        if (initialised(s).closed()) return "<tabletop.Simulation (closed)>";
        return with(s, [](SteppedScene& x) {
          char text[120];
          std::snprintf(text, sizeof text, " mode=%s entities=%zu time=%.6g s steps=%ld timestep=%.6g s>",
                        std::string(x.simulation().modeName()).c_str(), x.scenario().entities.size(),
                        x.simulation().time(), x.simulation().steps(), x.scenario().settings.timestep);
          return "<tabletop.Simulation '" + shownText(x.scenario().name, 40) + "'" + text;
        });
      });
}

}  // namespace tabletop::python
