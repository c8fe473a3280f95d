#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "core/SimulationMode.h"
#include "core/Settings.h"
#include "scenario/Scenario.h"

namespace CLI {
class App;
}

namespace tabletop {

/// Exit statuses of every tabletop command.
enum ExitStatus : int {
  kExitOk = 0,
  kExitFailure = 1,   ///< an unexpected failure inside tabletop
  kExitBadInput = 2,  ///< a scenario or command line that cannot be run
  kExitDiverged = 3,  ///< a run diverged; what it had is printed, marked incomplete
  kExitInterrupted = 130,  ///< stopped by Ctrl-C (SIGINT) or SIGTERM; outputs completed so far kept
};

/// A scenario to run: a file, a shipped scene's name, or a text built into
/// the executable.
struct ScenarioSource {
  std::string name;  ///< the path or name as given, or the built-in scenario's file name
  std::optional<std::string> text;
};

/// What `tabletop run` was asked to do.
struct RunOptions {
  std::vector<ScenarioSource> scenarios;
  bool json = false;
  SimulationMode mode = SimulationMode::Bullet;
  std::optional<double> timestep;
  std::optional<int> iterations;
  std::optional<Integrator> integrator;
  std::optional<double> duration;
  std::optional<int> threads;  ///< --threads, else TABLETOP_THREADS; unset: every core
  std::optional<std::string> outFile;  ///< write the output here, whole or not at all
  std::optional<std::string> traceFile;  ///< write every step's motions here (CSV), for one scenario
  double traceMaxMegabytes = 1024.0;     ///< the largest trace written, MB
  std::optional<double> tolerance;       ///< m: pick the cheapest settings the front says meet it
  std::string frontFile;  ///< where --tolerance reads the front; empty: the shipped one (DataPaths.h)
};

/// Declares run's options (all but the scenario list) on `command`; with
/// `withMode`, also --mode.
void addRunOptions(CLI::App& command, RunOptions& options, bool withMode = true);

/// Reads a scenario (a file, else the shipped scene of that name: sceneFile,
/// scenario/ShippedScenes.h) and resolves its settings once, into
/// scenario.settings, which every mode then reads: the file's, then
/// --tolerance's choice (what it chose and why, a line each, goes to
/// `choiceLines` if given), then --timestep, --iterations, --integrator and
/// --duration; and the threads to use (--threads, TABLETOP_THREADS, else
/// every core). Throws ScenarioError, also for a bad front file.
Scenario loadScenario(const ScenarioSource& source, const RunOptions& options,
                      std::vector<std::string>* choiceLines = nullptr);

/// Runs every scenario, then prints all outcomes to `out` (text, or JSON:
/// one document, runDocument(), for one scenario as for several). Problems go to `err`,
/// one line each, and then nothing is printed to `out`. A run that
/// diverges is printed marked incomplete, its error goes to `err`, and the
/// status is kExitDiverged. Ctrl-C or SIGTERM stops it between two steps
/// with kExitInterrupted, leaving no temporary file.
int runScenarios(const RunOptions& options, std::ostream& out, std::ostream& err);

/// Parses `argv` with CLI11 and runs `command`'s callback; maps --help to
/// 0 and usage errors to kExitBadInput.
int parseAndRun(CLI::App& app, int argc, char** argv, int& status);

}  // namespace tabletop
