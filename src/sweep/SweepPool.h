#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "io/ProcessPool.h"
#include "sweep/SweepRun.h"

namespace tabletop {

/// Runs `count` runs of `spec` from `first` on, handing each row to `onRow`
/// in run order (whatever order they finish in). With `jobs` > 1 the runs
/// go to that many worker processes (io/ProcessPool.h), each computed
/// exactly as in a single process. `stop` is asked between rows (and, with
/// one job, after every step); once it says true the pool returns, the
/// rows handed over being all complete. Throws std::runtime_error when a
/// worker cannot be started or dies.
void runSweepPool(const SweepSpec& spec, std::size_t first, std::size_t count, int jobs,
                  const std::function<void(const SweepRow&)>& onRow, const std::function<bool()>& stop);

/// As runSweepPool, but the runs go to one `program` (runBridgePool): it is
/// sent the spec whole (SweepSpec::selfContained) on one line, then run
/// numbers, and writes back each run's row as a JSON array on a line, in
/// any order (a bridge to a cluster: DaskBridge.h).
void runSweepBridge(const SweepSpec& spec, std::size_t first, std::size_t count, const std::vector<std::string>& program,
                    const std::function<void(const SweepRow&)>& onRow, const std::function<bool()>& stop);

}  // namespace tabletop
