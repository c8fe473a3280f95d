#pragma once

#include <pybind11/pybind11.h>

namespace tabletop {

/// Adds tabletop.sweep() and the one-run function a cluster's workers call
/// to the module.
void addSweep(pybind11::module_& m);

}  // namespace tabletop
