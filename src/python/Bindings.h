#pragma once

#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/BodyMotion.h"

#include "python/SimulationObject.h"
#include "scenario/Scenario.h"

/// The module's parts, each adding its functions and classes to the module;
/// TabletopModule.cpp calls them in order (the scenarios first: the other
/// parts' signatures name tabletop.Scenario). A new part declares its
/// bindX here and is called there.
namespace tabletop::python {

/// Scenario, load, scene, run, shipped_scenes, and the module's exceptions.
void bindScenarios(pybind11::module_& m);
/// Simulation.
void bindSimulation(pybind11::module_& m);
/// The part of each body's motion an array holds.
enum class Motion { Position, Orientation, Velocity, Spin };
/// One row per body of `part` of `motions`: a fresh NumPy array, read-only
/// (a write raises rather than changing nothing).
pybind11::array_t<double> motionRows(const std::vector<BodyMotion>& motions, Motion part);

/// Simulation.__init__: builds `scene` into `self`, made by __new__ (a
/// RuntimeError when it already holds one); `threads` as resolved() reads it.
void initialise(const pybind11::handle& self, const pybind11::object& scene, const std::string& mode, bool script,
                std::optional<double> timestep, const pybind11::object& iterations, std::optional<std::string> integrator,
                const pybind11::object& threads);

/// Simulation's readings: state arrays, contacts, repr (SimulationReadings.cpp).
void bindSimulationReadings(pybind11::class_<SimulationObject>& simulation);
/// Simulation's saved states: reset, get_state, set_state, copies, pickles,
/// and the State class (SimulationStates.cpp).
void bindSimulationStates(pybind11::class_<SimulationObject>& simulation);
/// write_png.
void bindImages(pybind11::module_& m);

/// The entities' names, in scenario order (the order of every array).
std::vector<std::string> entityNames(const Scenario& scenario);

}  // namespace tabletop::python
