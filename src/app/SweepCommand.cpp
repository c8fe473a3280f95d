#include "app/SweepCommand.h"

#include <algorithm>
#include <iostream>

#include "app/DataPaths.h"
#include "app/GnuplotFile.h"
#include "app/InterruptGuard.h"
#include "app/OptionChecks.h"
#include "app/Progress.h"
#include "app/RunCommand.h"
#include "app/SweepMap.h"
#include "scenario/ScenarioError.h"
#include "scenario/ValueRanges.h"
#include "sweep/DaskBridge.h"
#include "sweep/SweepPool.h"
#include "sweep/SweepTable.h"

namespace tabletop {
namespace {

// "bullet agrees with the rules in 61 of 100 runs", a clause per mode compared.
std::string agreementSummary(const SweepSpec& spec, const std::vector<SweepRow>& rows) {
  const std::vector<std::string> columns = sweepColumns(spec);
  std::string s;
  for (SimulationMode m : spec.modes) {
    const auto it = std::find(columns.begin(), columns.end(), std::string(toString(m)) + ".agrees");
    if (it == columns.end()) continue;
    const std::size_t c = static_cast<std::size_t>(it - columns.begin());
    std::size_t agree = 0;
    for (const SweepRow& row : rows) agree += row.at(c) == true;
    s += std::string(s.empty() ? "; " : ", ") + std::string(toString(m)) + " agrees with the rules in " +
         std::to_string(agree) + " of " + std::to_string(rows.size()) + (rows.size() == 1 ? " run" : " runs");
  }
  return s;
}

// The random runs of --random, --seed and --rate as a spec.
std::string randomSpec(const SweepOptions& options) {
  nlohmann::json random{{"runs", *options.random}};
  if (options.rate) random["rate"] = *options.rate;
  return nlohmann::json{{"version", 1}, {"name", "random"}, {"seed", options.seed}, {"random", random}}.dump();
}

// "; 2 of 1000 runs not stable: seed 42 (energy gain 0.1 J), ..." (at most
// kShown seeds), or "; all stable".
std::string stabilitySummary(const SweepSpec& spec, const std::vector<SweepRow>& rows, std::size_t& unstable) {
  constexpr std::size_t kShown = 10;
  const std::vector<std::string> columns = sweepColumns(spec);
  const auto at = [&columns](const char* name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  const std::size_t stable = at("bullet.stable"), reason = at("bullet.reason"), seed = at("seed");
  std::string seeds;
  unstable = 0;
  for (const SweepRow& row : rows) {
    if (row.at(stable) == true) continue;
    if (++unstable <= kShown) {
      seeds += std::string(unstable > 1 ? ", " : ": ") + "seed " + row.at(seed).dump() + " (" +
               row.at(reason).get<std::string>() + ")";
    }
  }
  if (unstable == 0) return "; all stable";
  return "; " + std::to_string(unstable) + " of " + std::to_string(rows.size()) + " not stable" + seeds +
         (unstable > kShown ? ", ..." : "");
}

}  // namespace

void addSweepOptions(CLI::App& command, SweepOptions& options) {
  CLI::Option* spec =
      command.add_option("SPEC", options.spec, "Sweep spec (JSON): a base scene, the parameters to vary, the modes");
  CLI::Option* random =
      command
          .add_option("--random", options.random,
                      "Run N random scenes (2-5 bodies, 1-4 pushes each) in full physics in place of a spec, and "
                      "check each stays finite, in the world and gains no energy (docs/sweep.md)")
          ->check(CLI::Range(std::size_t{1}, SweepSpec::kMaxRuns))
          ->excludes(spec);
  spec->excludes(random);
  command.add_option("--seed", options.seed, "The first random scene's seed (default 0)")->needs(random);
  command.add_option("--rate", options.rate, "The random runs' step rate, Hz (default: the default settings')")
      ->check(finiteRange(1.0 / ranges::kTimestep.hi, 1.0 / ranges::kTimestep.lo))
      ->needs(random);
  command.add_option("--out", options.out,
                     "Write the table to PREFIX.csv and PREFIX.jsonl, a row as each run ends; a sweep "
                     "stopped goes on from where it stopped (default: JSON lines on standard output)");
  CLI::Option* jobs = command.add_option("--jobs", options.jobs, "Worker processes (default: every core)")
                          ->check(CLI::Range(1, kMaxJobs));
  command
      .add_option("--scheduler", options.scheduler,
                  "Run on the workers of the Dask cluster whose scheduler is at tcp://HOST:PORT (python3 with "
                  "dask.distributed and the tabletop module here, the module on the workers)")
      ->excludes(jobs);
  command.add_option("--plot", options.plot,
                     "Draw where the modes agree with the rules over the first two parameters (FILE.png or FILE.svg)");
}

int runSweep(const SweepOptions& options, std::ostream& out, std::ostream& err) {
  if (options.plot) {
    if (const std::string problem = plotNameProblem(*options.plot); !problem.empty()) {
      err << "tabletop sweep: --plot: " << problem << "\n";
      return kExitBadInput;
    }
  }
  if (options.scheduler) {
    if (const std::string problem = schedulerProblem(*options.scheduler); !problem.empty()) {
      err << "tabletop sweep: --scheduler: " << problem << "\n";
      return kExitBadInput;
    }
  }
  if (!options.random && options.spec.empty()) {
    err << "tabletop sweep: a SPEC or --random N is required\n";
    return kExitBadInput;
  }
  SweepSpec spec;
  try {
    spec = options.random ? loadSweepText(randomSpec(options), "--random", shippedScenarios())
                          : loadSweepFile(options.spec, shippedScenarios());
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) err << line << "\n";
    return kExitBadInput;
  }
  const InterruptGuard interrupt;
  std::vector<SweepRow> rows;
  std::optional<SweepTable> table;
  std::size_t first = 0;
  try {
    if (options.out) {
      table.emplace(*options.out, spec);
      rows = table->rows();
      first = table->done();
    }
    const std::vector<std::string> columns = sweepColumns(spec);
    const std::size_t total = spec.runs();
    Progress progress(err);
    progress.start(static_cast<long>(total));
    progress.set(static_cast<long>(first), "runs");
    const auto onRow = [&](const SweepRow& row) {
      if (table)
        table->append(row);
      else
        out << jsonLine(columns, row) << std::flush;
      rows.push_back(row);
      progress.set(static_cast<long>(rows.size()), "runs");
    };
    const auto stop = [&interrupt] { return interrupt.requested(); };
    if (options.scheduler) {
      runSweepBridge(spec, first, total - first, daskBridgeCommand(*options.scheduler), onRow, stop);
    } else {
      runSweepPool(spec, first, total - first, options.jobs > 0 ? options.jobs : availableThreads(), onRow, stop);
    }
  } catch (const std::exception& e) {
    err << "tabletop sweep: " << e.what() << "\n";
    return kExitFailure;
  }
  const std::string where = table ? " in " + table->csvPath() + " and " + table->jsonPath() : "";
  if (interrupt.requested()) {
    err << "tabletop sweep: interrupted after " << rows.size() << " of " << spec.runs() << " runs; they are kept"
        << where << (table ? "; the same command goes on from there" : "") << "\n";
    return kExitInterrupted;
  }
  std::size_t unstable = 0;
  (table ? out : err) << spec.name << ": " << rows.size() << (rows.size() == 1 ? " run" : " runs")
                      << (first ? " (" + std::to_string(first) + " done before)" : "") << where
                      << (spec.random ? stabilitySummary(spec, rows, unstable) : agreementSummary(spec, rows)) << "\n";
  if (options.plot) {
    if (const std::string problem = writeSweepMap(spec, rows, *options.plot); !problem.empty()) {
      err << "tabletop sweep: " << problem << "\n";
      return kExitFailure;
    }
  }
  return unstable > 0 ? kExitFailure : kExitOk;
}

}  // namespace tabletop
