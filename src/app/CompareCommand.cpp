#include "app/CompareCommand.h"

#include <cmath>
#include <iostream>

#include "app/GnuplotFile.h"
#include "app/InterruptGuard.h"
#include "app/Progress.h"
#include "app/TrajectoryPlot.h"
#include "scenario/ScenarioError.h"
#include "sim/ModeComparison.h"

namespace tabletop {

int compareScenario(const CompareOptions& options, std::ostream& out, std::ostream& err) {
  // The plot's name is checked before anything runs.
  if (options.plot) {
    if (const std::string problem = plotNameProblem(*options.plot); !problem.empty()) {
      err << "tabletop compare: --plot: " << problem << "\n";
      return kExitBadInput;
    }
  }
  const InterruptGuard interrupt;
  const ScenarioSource& source = options.run.scenarios.at(0);
  Comparison comparison;
  Scenario scenario;
  try {
    scenario = loadScenario(source, options.run);
    // The bar counts the steps of the three runs up to their duration.
    Progress progress(err);
    progress.start(3 * std::lround(scenario.settings.duration / scenario.settings.timestep));
    long steps = 0;
    comparison = compareModes(scenario, scenario.settings, [&](const Simulation&) {
      interrupt.throwIfRequested();
      progress.set(++steps, "three modes");
    });
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) err << line << "\n";
    return kExitBadInput;
  } catch (const InterruptGuard::Interrupted&) {
    err << "tabletop compare: interrupted; nothing written\n";
    return kExitInterrupted;
  }
  if (options.run.json) {
    out << comparisonJson(comparison).dump(2) << "\n";
  } else {
    out << formatComparison(comparison);
  }
  int status = kExitOk;
  for (const RunResult& r : comparison.runs) {
    if (!r.complete) {
      err << r.file << ": mode " << r.mode << ": " << r.failure << "\n";
      status = kExitDiverged;
    }
  }
  if (options.plot) {
    const std::string problem = writeTrajectoryPlot(comparison, scenario.table, *options.plot);
    if (interrupt.requested()) {
      err << "tabletop compare: interrupted; no plot written\n";
      return kExitInterrupted;
    }
    if (!problem.empty()) {
      err << "tabletop compare: " << problem << "\n";
      return kExitFailure;
    }
  }
  return status;
}

}  // namespace tabletop
