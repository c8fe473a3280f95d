#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace tabletop {

/// What `tabletop sweep` was asked to do.
struct SweepOptions {
  std::string spec;                 ///< the sweep spec (JSON), unless `random`
  std::optional<std::size_t> random;  ///< --random N: the random stability runs, in place of a spec
  std::uint64_t seed = 0;             ///< --seed: the first random scene's seed
  std::optional<double> rate;         ///< --rate HZ: the random runs' step rate (default: the settings')
  std::optional<std::string> out;   ///< PREFIX: PREFIX.csv and PREFIX.jsonl, resumed if begun
  int jobs = 0;                     ///< worker processes; 0: every core
  std::optional<std::string> plot;  ///< --plot FILE (.png or .svg): the map of the first two parameters
  std::optional<std::string> scheduler;  ///< --scheduler tcp://HOST:PORT: the runs go to that Dask cluster
};

/// Declares sweep's options on `command`.
void addSweepOptions(CLI::App& command, SweepOptions& options);

/// Runs a sweep: every run of the spec not already in the table, on
/// `jobs` processes (or on the Dask cluster of --scheduler), each row appended as it finishes (in run order); with
/// no --out the rows go to `out` as JSON lines. A bar with the time left
/// on `err`; Ctrl-C keeps the rows done (status 130), and a second sweep
/// with the same --out goes on from there. Then a summary line, and the
/// map with --plot. With --random N the runs are the random stability
/// runs (SweepRandom), the summary the count that is not stable, and the
/// status 1 when any is not. A bad spec is kExitBadInput, one located line per
/// problem.
int runSweep(const SweepOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tabletop
