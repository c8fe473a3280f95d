#pragma once

#include <string>

#include "core/TableSpec.h"
#include "sim/ModeComparison.h"

namespace tabletop {

/// Writes a top-down picture of every entity's trajectory in the three
/// modes over the table outline, with gnuplot: PNG for a .png file, SVG for
/// a .svg file. The picture is written to a temporary file next to `path`
/// and renamed into place, so `path` is never half-written.
/// Returns an empty string, or a one-line reason it could not.
std::string writeTrajectoryPlot(const Comparison& comparison, const TableSpec& table, const std::string& path);

}  // namespace tabletop
