#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/ScriptPlayer.h"
#include "sweep/SweepSpec.h"

namespace tabletop {

/// One row of a sweep's table: a value per column.
using SweepRow = std::vector<nlohmann::json>;

/// The columns of `spec`'s table, in order: "run", each parameter's name,
/// then per mode ("bullet.") what the spec records: each entity's x, y, z,
/// yaw and status ("bullet.A.x"), the events, against the rules (when the
/// rules run too) each entity's from_rules and verdict with the mode's
/// distance, agrees and reason, the wall time wall_s, the state_hash and
/// the failure of a run that diverged; last, the problem of a run that
/// could not start (bodies overlapping), else "".
std::vector<std::string> sweepColumns(const SweepSpec& spec);

/// The columns that differ from one running of the same sweep to the next
/// (the wall times); every other cell is the same in every process.
bool isTimingColumn(const std::string& column);

/// Runs run `index` of `spec` in each of its modes and returns its row.
/// `afterStep` sees every step (and may throw to stop the run).
SweepRow runSweepRow(const SweepSpec& spec, std::size_t index, const StepObserver& afterStep = {});

/// The first reason of a verdict ("stopped short" of "diverges: stopped
/// short, rotated"), or "" for "agrees".
std::string firstReason(const std::string& verdict);

}  // namespace tabletop
