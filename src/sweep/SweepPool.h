#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sweep/SweepRun.h"

namespace tabletop {

/// The most worker processes a sweep starts.
inline constexpr int kMaxJobs = 256;

/// The most runs a bridge (runSweepBridge) holds at once.
inline constexpr std::size_t kMaxBridgeRuns = 4096;

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

/// As runSweepPool, but the runs go to one `program` started with its
/// standard input and output as pipes: it is sent the spec whole
/// (SweepSpec::selfContained) on one line, then run numbers, a line each,
/// up to kMaxBridgeRuns ahead, and writes back each run's row as a JSON
/// array on a line, in any order (a bridge to a cluster: DaskBridge.h).
void runSweepBridge(const SweepSpec& spec, std::size_t first, std::size_t count, const std::vector<std::string>& program,
                    const std::function<void(const SweepRow&)>& onRow, const std::function<bool()>& stop);

}  // namespace tabletop
