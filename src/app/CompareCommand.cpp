#include "app/CompareCommand.h"

#include <iostream>

#include "app/TrajectoryPlot.h"
#include "scenario/ScenarioError.h"
#include "sim/ModeComparison.h"

namespace tabletop {

int compareScenario(const CompareOptions& options, std::ostream& out, std::ostream& err) {
  const ScenarioSource& source = options.run.scenarios.at(0);
  Comparison comparison;
  Scenario scenario;
  try {
    Settings settings;
    scenario = loadScenario(source, options.run, settings);
    comparison = compareModes(scenario, settings);
  } catch (const ScenarioError& e) {
    for (const std::string& line : e.lines()) err << line << "\n";
    return kExitBadInput;
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
    if (!problem.empty()) {
      err << "tabletop compare: " << problem << "\n";
      return kExitFailure;
    }
  }
  return status;
}

}  // namespace tabletop
