#include "app/RunCommand.h"

#include <cmath>
#include <exception>
#include <iostream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>

#include "app/DataPaths.h"
#include "app/InterruptGuard.h"
#include "app/Progress.h"
#include "app/OptionChecks.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "scenario/ShippedScenes.h"
#include "sim/ResultFormat.h"
#include "sim/SceneBuilder.h"
#include "sim/ScriptRunner.h"
#include "measure/ToleranceFront.h"
#include "sim/TraceWriter.h"

namespace tabletop {
namespace {

// A --duration that ends before some of the script's actions: they will
// not run, which the user may not have meant. One located line each.
void warnCutScript(const Scenario& scenario, const Settings& settings, std::vector<std::string>& lines) {
  for (const Action& a : scenario.script) {
    if (!a.at || *a.at <= settings.duration) continue;
    std::ostringstream why;
    why << "warning: the duration (" << settings.duration << " s) ends before this action's time (" << *a.at
        << " s); it and those after it will not run";
    std::vector<Problem> p{{a.path + "/t", why.str()}};
    for (const std::string& line : ScenarioError(scenario, p).lines()) lines.push_back(line);
    return;
  }
}

}  // namespace

void addRunOptions(CLI::App& command, RunOptions& options, bool withMode) {
  command.add_flag("--json", options.json, "Print the outcome as JSON instead of text");
  if (withMode) {
    enumOption(command.add_option("--mode", options.mode,
                                  "bullet: full physics (the default); compat: Bullet held to the report's rules; "
                                  "rules: the report's rules alone"),
               kAllModes);
  }
  command.add_option("--timestep", options.timestep, "Fixed timestep in seconds (overrides the scenario)")
      ->check(finiteRange(kMinTimestep, kMaxTimestep));
  command.add_option("--iterations", options.iterations, "Solver iterations per step (overrides the scenario)")
      ->check(CLI::Range(1, 10000));
  enumOption(command.add_option("--integrator", options.integrator,
                                "How positions follow velocities: trapezoid (second order, the default) or euler "
                                "(Bullet's own); overrides the scenario"),
             kAllIntegrators);
  command.add_option("--tolerance", options.tolerance,
                     "Error in metres to meet: picks the cheapest timestep, iterations and integrator the bench's "
                     "front says meet it for the scene's kinds of motion, and says why (overrides the scenario; "
                     "--timestep, --iterations and --integrator override it)")
      ->check(finiteRange(1e-9, 1.0));
  command.add_option("--front", options.frontFile,
                     "The front --tolerance reads (default: the shipped data/tolerance_front.json; made by tabletop bench --write-front)");
  command.add_option("--duration", options.duration, "Longest simulated time in seconds (overrides the scenario)")
      ->check(finiteRange(1e-9, 3600.0));
  addThreadsOption(command, options.threads);
}

Scenario loadScenario(const ScenarioSource& source, const RunOptions& options,
                      std::vector<std::string>* choiceLines) {
  Scenario scenario =
      source.text ? ScenarioLoader::loadText(*source.text, source.name)
                  : ScenarioLoader::loadFile(sceneFile(source.name, shippedScenarios(), "tabletop list"));
  Settings& settings = scenario.settings;
  if (options.tolerance) {
    const std::string front = options.frontFile.empty() ? shippedFront() : options.frontFile;
    const ToleranceChoice choice = ToleranceFront::load(front).choose(scenario, *options.tolerance);
    settings = choice.settings;
    if (choiceLines) {
      std::ostringstream head;
      head << scenario.name << ": for an error of at most " << *options.tolerance << " m, "
           << (choice.met ? "chose " : "could not meet it everywhere; chose ") << 1.0 / settings.timestep << " Hz ("
           << settings.timestep << " s), " << describeSolver(settings.solver, settings.iterations) << ", "
           << toString(settings.integrator)
           << "; by kind of motion, the cheapest measured settings within it:";
      choiceLines->push_back(head.str());
      for (const std::string& r : choice.reasons) choiceLines->push_back("  " + r);
    }
  }
  if (options.timestep) settings.timestep = *options.timestep;
  if (options.iterations) settings.iterations = *options.iterations;
  if (options.integrator) settings.integrator = *options.integrator;
  if (options.duration) settings.duration = *options.duration;
  settings.threads = options.threads.value_or(availableThreads());
  const std::string tooLong = ScenarioLoader::runSizeProblem(settings, scenario.entities.size());
  if (!tooLong.empty()) throw ScenarioError(scenario, {{"/settings", tooLong + " with the command line's settings"}});
  return scenario;
}

int runScenarios(const RunOptions& options, std::ostream& out, std::ostream& err) {
  if (options.traceFile && options.scenarios.size() != 1) {
    err << "tabletop run: --trace: expected one scenario, got " << options.scenarios.size() << "\n";
    return kExitBadInput;
  }
  // Where the outputs go is checked before anything runs.
  for (const auto& [flag, file] : {std::pair{"--out", options.outFile}, std::pair{"--trace", options.traceFile}}) {
    if (!file) continue;
    if (const std::string problem = AtomicFile::destinationProblem(*file); !problem.empty()) {
      err << "tabletop run: " << flag << ": " << problem << "\n";
      return kExitFailure;
    }
  }
  // Both into one file would leave only the one renamed into place last.
  if (options.outFile && options.traceFile && AtomicFile::sameFile(*options.outFile, *options.traceFile)) {
    err << "tabletop run: --out and --trace name the same file ('" << shownText(*options.outFile) << "', '"
        << shownText(*options.traceFile) << "'); expected two files\n";
    return kExitBadInput;
  }
  const InterruptGuard interrupt;
  std::vector<RunResult> results;
  std::vector<std::string> choices;
  bool failed = false;
  std::optional<TraceWriter> trace;
  try {
    for (const ScenarioSource& source : options.scenarios) {
      try {
        const Scenario scenario = loadScenario(source, options, &choices);
        const Settings& settings = scenario.settings;
        std::vector<std::string> warnings;
        if (options.duration) warnCutScript(scenario, settings, warnings);
        for (const std::string& line : warnings) err << line << "\n";
        std::unique_ptr<Simulation> simulation = buildSimulation(scenario, settings, options.mode);
        // The bar counts steps up to the duration; a run that comes to rest ends sooner.
        Progress progress(err);
        progress.start(std::lround(settings.duration / settings.timestep));
        long steps = 0;
        const auto tick = [&interrupt, &progress, &steps, name = shownText(scenario.name)](const Simulation&) {
          interrupt.throwIfRequested();
          progress.set(++steps, name);
        };
        StepObserver observer = tick;
        if (options.traceFile) {
          std::vector<std::string> names;
          for (const EntitySpec& e : scenario.entities) names.push_back(e.name);
          trace.emplace(*options.traceFile, std::move(names), options.traceMaxMegabytes * 1e6);
          if (!trace->problem().empty()) {
            err << "tabletop run: --trace: " << trace->problem() << "\n";
            return kExitFailure;
          }
          trace->record(*simulation);
          observer = [&tick, &trace](const Simulation& s) {
            tick(s);
            trace->record(s);
          };
        }
        results.push_back(runScript(scenario, settings, *simulation, observer));
      } catch (const ScenarioError& e) {
        for (const std::string& line : e.lines()) err << line << "\n";
        failed = true;
      }
    }
  } catch (const InterruptGuard::Interrupted&) {
    err << "tabletop run: interrupted; nothing written\n";
    return kExitInterrupted;
  }
  if (failed) return kExitBadInput;
  if (trace) {
    if (const std::string problem = trace->commit(); !problem.empty()) {
      err << "tabletop run: --trace: " << problem << "\n";
      return kExitFailure;
    }
  }
  int status = kExitOk;
  for (const RunResult& r : results) {
    if (!r.complete) {
      err << r.file << ": " << r.failure << "\n";
      status = kExitDiverged;
    }
  }

  // What --tolerance chose goes with the text; beside JSON, to the error
  // stream, so the JSON stays one document.
  std::ostringstream text;
  for (const std::string& line : choices) (options.json ? err : text) << line << "\n";
  if (!choices.empty() && !options.json) text << "\n";
  if (options.json) {
    text << runDocument(results).dump(2) << "\n";
  } else {
    for (std::size_t i = 0; i < results.size(); ++i) text << (i ? "\n" : "") << formatText(results[i]);
  }
  if (!options.outFile) {
    out << text.str();
  } else if (const std::string problem = AtomicFile::write(*options.outFile, text.str()); !problem.empty()) {
    err << "tabletop run: --out: " << problem << "\n";
    return kExitFailure;
  }
  return status;
}

int parseAndRun(CLI::App& app, int argc, char** argv, int& status) {
  // A refused option is one line, like every other refusal.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("tabletop: ") + e.what() + " (--help lists the options)\n";
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  return status;
}

}  // namespace tabletop
