#pragma once

#include <string>
#include <vector>

#include "sweep/SweepRun.h"

namespace tabletop {

/// The gnuplot script of a sweep's map: one point per run at its first two
/// parameters' values, coloured by whether `mode` agrees with the rules
/// (its distance under compare's threshold) and otherwise by the first
/// reason it does not; or "" with `problem` set when the sweep cannot be
/// drawn so (fewer than two numeric parameters, no comparison with the rules).
std::string sweepMapScript(const SweepSpec& spec, const std::vector<SweepRow>& rows, std::string& problem);

/// Draws the map into `path` (.png or .svg); "" or what went wrong.
std::string writeSweepMap(const SweepSpec& spec, const std::vector<SweepRow>& rows, const std::string& path);

}  // namespace tabletop
