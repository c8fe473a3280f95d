#include "sweep/SweepPool.h"

#include <algorithm>

#include "io/ProcessPool.h"

namespace tabletop {
namespace {

struct Stopped {};

void runInProcess(const SweepSpec& spec, std::size_t first, std::size_t count,
                  const std::function<void(const SweepRow&)>& onRow, const std::function<bool()>& stop) {
  try {
    for (std::size_t i = first; i < first + count && !stop(); ++i) {
      onRow(runSweepRow(spec, i, [&stop](const Simulation&) {
        if (stop()) throw Stopped{};
      }));
    }
  } catch (const Stopped&) {
  }
}

}  // namespace

void runSweepPool(const SweepSpec& spec, std::size_t first, std::size_t count, int jobs,
                  const std::function<void(const SweepRow&)>& onRow, const std::function<bool()>& stop) {
  if (std::min<std::size_t>(std::clamp(jobs, 1, kMaxJobs), count) <= 1) {
    return runInProcess(spec, first, count, onRow, stop);
  }
  runProcessPool(first, count, jobs, [&spec](std::size_t index) { return runSweepRow(spec, index); }, onRow, stop);
}

void runSweepBridge(const SweepSpec& spec, std::size_t first, std::size_t count, const std::vector<std::string>& program,
                    const std::function<void(const SweepRow&)>& onRow, const std::function<bool()>& stop) {
  // The bridge's first line is the spec, whole, with its scene.
  runBridgePool(spec.selfContained(), first, count, program, onRow, stop);
}

}  // namespace tabletop
