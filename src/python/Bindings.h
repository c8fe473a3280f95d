#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

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
/// write_png.
void bindImages(pybind11::module_& m);

/// The entities' names, in scenario order (the order of every array).
std::vector<std::string> entityNames(const Scenario& scenario);

}  // namespace tabletop::python
