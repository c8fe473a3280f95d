#pragma once

#include <string>

#include "core/TableSpec.h"
#include "sim/ModeComparison.h"

namespace tabletop {

/// The gnuplot script of the picture below (without its terminal): every
/// entity's trajectory over the table outline, one colour per entity and
/// one line style and end marker per mode, a mark at each start, the
/// names at the starts moved apart where they would overlap, and a legend
/// of entities and modes outside the plot.
std::string trajectoryPlotScript(const Comparison& comparison, const TableSpec& table);

/// Writes a top-down picture of every entity's trajectory in the three
/// modes over the table outline, with gnuplot: PNG for a .png file, SVG for
/// a .svg file. The picture is written to a temporary file next to `path`
/// and renamed into place, so `path` is never half-written.
/// Returns an empty string, or a one-line reason it could not.
std::string writeTrajectoryPlot(const Comparison& comparison, const TableSpec& table, const std::string& path);

}  // namespace tabletop
