#pragma once

#include <cstddef>
#include <functional>

#include "sweep/SweepRun.h"

namespace tabletop {

/// The most worker processes a sweep starts.
inline constexpr int kMaxJobs = 256;

/// The cores this machine offers (at least 1, at most kMaxJobs).
int availableCores();

/// Runs `count` runs of `spec` from `first` on, handing each row to `onRow`
/// in run order (whatever order they finish in). With `jobs` > 1 the runs
/// go to that many worker processes forked from this one: Bullet keeps
/// global state (its profiler, callbacks, thresholds), so two worlds never
/// step in one process at once, and each run is computed exactly as in a
/// single process. `stop` is asked between rows (and, with one job, after
/// every step); once it says true the pool ends its workers and returns,
/// the rows handed over being all complete. Throws std::runtime_error when
/// a worker cannot be started or dies.
void runSweepPool(const SweepSpec& spec, std::size_t first, std::size_t count, int jobs,
                  const std::function<void(const SweepRow&)>& onRow, const std::function<bool()>& stop);

}  // namespace tabletop
