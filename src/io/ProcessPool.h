#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/WorkerThreads.h"

namespace tabletop {

/// The most worker processes a pool starts (as many as threads:
/// availableThreads() says how many cores there are).
inline constexpr int kMaxJobs = kMaxThreads;

/// The most jobs a bridge (runBridgePool) holds at once.
inline constexpr std::size_t kMaxBridgeRuns = 4096;

/// One job's result: a row of JSON values whose first is the job's index.
using PoolRow = std::vector<nlohmann::json>;
/// What a worker does with job `index`; run in the worker process.
using PoolJob = std::function<PoolRow(std::size_t index)>;

/// Runs jobs [first, first + count) on `jobs` worker processes forked from
/// this one (at least 2), each job computed by `job` in a worker and its row
/// sent back as one JSON line; hands each row to `onRow` in job order,
/// whatever order they finish in. Processes, not threads: Bullet keeps
/// global state (its profiler, callbacks, thresholds), so two worlds never
/// step in one process at once, and a job is computed exactly as in a
/// single process. `stop` is asked between rows; once it says true the
/// pool ends its workers and returns, the rows handed over being all
/// complete. Throws std::runtime_error when a worker cannot be started or
/// dies.
void runProcessPool(std::size_t first, std::size_t count, int jobs, const PoolJob& job,
                    const std::function<void(const PoolRow&)>& onRow, const std::function<bool()>& stop);

/// As runProcessPool, but the jobs go to one `program` started with its
/// standard input and output as pipes: it is sent `firstLine`, then job
/// numbers, a line each, up to kMaxBridgeRuns ahead, and writes back each
/// job's row as a JSON array on a line, in any order (a bridge to a
/// cluster).
void runBridgePool(const std::string& firstLine, std::size_t first, std::size_t count,
                   const std::vector<std::string>& program, const std::function<void(const PoolRow&)>& onRow,
                   const std::function<bool()>& stop);

}  // namespace tabletop
