#include "app/BenchCommand.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/BenchTables.h"
#include "app/DataPaths.h"
#include "app/GnuplotFile.h"
#include "app/InterruptGuard.h"
#include "app/OptionChecks.h"
#include "app/Progress.h"
#include "app/RunCommand.h"
#include "core/Text.h"
#include "io/AtomicFile.h"
#include "io/ProcessPool.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "measure/BenchRuns.h"
#include "measure/Benchmark.h"
#include "measure/LawSweep.h"
#include "scenes/CubeField.h"
#include "measure/ModelSwitch.h"
#include "sim/ResultFormat.h"
#include "sim/SceneBuilder.h"
#include "measure/StabilityProbe.h"
#include "sim/ScriptRunner.h"
#include "measure/ToleranceFront.h"

namespace tabletop {
namespace {

std::vector<std::string> defaultScenes(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir + "/analytic", ec)) {
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  }
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("example", 0) == 0 && e.path().extension() == ".json") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}


// What the measuring loops report to a terminal, and how Ctrl-C stops them.
MeasureHooks hooks(const InterruptGuard& interrupt, Progress& progress) {
  return {[&interrupt] { return interrupt.requested(); }, [&progress](long total) { progress.start(total); },
          [&progress](const std::string& done) { progress.advance(done); }};
}

}  // namespace

void addBenchOptions(CLI::App& command, BenchOptions& options) {
  command.add_option("SCENARIO", options.scenarios,
                     "Scenes to measure (default: scenarios/analytic/*.json and the report's examples)");
  command.add_option("--scenarios", options.scenarioDir, "Where the default scenes are (default: the shipped ones)");
  command.add_option("--cases", options.cases, "Only scenes whose name contains PATTERN");
  command.add_option("--out-dir", options.outDir, "Write DIR/bench.csv and DIR/bench_SCENE.png (log-log plots)");
  command.add_option("--write-front", options.frontFile,
                     "Write the analytic cases' full-physics fronts to FILE, for run --tolerance "
                     "(the shipped one is data/tolerance_front.json)");
  command.add_flag("--json", options.json, "Print the measurements as JSON instead of tables");
  command.add_option("--repeats", options.repeats, "Timed runs per setting, after a warm-up (default 5)")
      ->check(CLI::Range(1, 1000));
  command.add_option("--jobs", options.jobs,
                     "Worker processes timing the sweep's settings at once, each setting on one core, and running "
                     "the laws' scenes (default: every core)")
      ->check(CLI::Range(1, kMaxJobs));
  command.add_option("--rates", options.rates, "Step rates to sweep, Hz (default 30,60,...,4000)")
      ->delimiter(',')
      ->check(finiteRange(1.0 / kMaxTimestep, 1.0 / kMinTimestep));
  command.add_option("--iterations", options.iterations, "Solver iterations to sweep (default 4,10,20,50)")
      ->delimiter(',')
      ->check(CLI::Range(1, 10000));
  enumOption(command.add_option("--integrators", options.integrators, "Integrators to sweep (default euler,trapezoid)")
                 ->delimiter(','),
             kAllIntegrators);
  command.add_flag("--sweep", options.sweep, "Sweep the settings (the default when no section is asked for)");
  command.add_flag("--switches", options.switches,
                   "Measure each model switch (sleeping, legs, floor pairs, broadphase) on every scene");
  command.add_option("--scale", options.scale,
                     "Time the cube field of these sizes with each model switch (e.g. 10,100,1000,10000)")
      ->delimiter(',')
      ->check(CLI::Range(1, 100000));
  command.add_option("--piles", options.piles,
                     "Drop piles of these many mixed bodies (e.g. 100,300,1000) in tabletop and in Bullet's own "
                     "pipeline: cost, growth exponent, and once settled drift, penetration, energy gain")
      ->delimiter(',')
      ->check(CLI::Range(1, 100000));
  command.add_option("--pile-budget", options.pileBudget,
                     "Wall seconds a pile's tabletop run may take before it stops and larger piles are left out "
                     "(default 120)")
      ->check(finiteRange(0.001, 86400.0));
  addThreadsOption(command, options.threads)
      ->description("Threads the piles are run on a second time, against one (default: TABLETOP_THREADS, else "
                    "every core); any count gives the same states to the bit");
  command.add_flag("--hard", options.hard,
                   "Run each hard case (SCENARIOS/hard) once at its own settings: cost, drift, penetration, "
                   "speed at rest, energy gain");
  command.add_flag("--baseline", options.baseline,
                   "Time each scene at each of --rates against the same scene in Bullet's own default pipeline");
  command.add_flag("--laws", options.laws,
                   "Hold every shape on the table, the floor, a slab and a drum to the sliding, rolling, step, "
                   "spinning and bouncing laws, at each of --rates: the worst error against the closed form");
  enumOption(command.add_option("--modes", options.modes,
                                "Modes to sweep (default bullet,compat,rules; compat and rules at the scene's own "
                                "iterations)")
                 ->delimiter(','),
             kAllModes);
}

int runBench(const BenchOptions& asked, std::ostream& out, std::ostream& err) {
  BenchOptions options = asked;
  if (options.scenarioDir.empty()) options.scenarioDir = shippedScenarios();
  std::vector<BenchScene> scenes;
  const std::vector<std::string> files = options.scenarios.empty() ? defaultScenes(options.scenarioDir)
                                                                   : options.scenarios;
  bool bad = false;
  for (const std::string& f : files) {
    try {
      Scenario s = ScenarioLoader::loadFile(f);
      if (!options.cases || s.name.find(*options.cases) != std::string::npos) scenes.emplace_back(std::move(s));
    } catch (const ScenarioError& e) {
      for (const std::string& line : e.lines()) err << line << "\n";
      bad = true;
    }
  }
  if (bad) return kExitBadInput;
  if (scenes.empty()) {
    err << "tabletop bench: no scene to measure (looked in " << options.scenarioDir
        << (options.cases ? " for names containing '" + *options.cases + "'" : std::string()) << ")\n";
    return kExitBadInput;
  }
  if (options.outDir) {
    std::error_code ec;
    std::filesystem::create_directories(*options.outDir, ec);
    if (ec || !std::filesystem::is_directory(*options.outDir)) {
      err << "tabletop bench: --out: cannot make the directory '" << *options.outDir << "'\n";
      return kExitFailure;
    }
  }

  const bool sweepAsked =
      options.sweep ||
      (!options.switches && options.scale.empty() && options.piles.empty() && !options.hard && !options.laws && !options.baseline);
  const SweepGrid grid{options.rates, options.iterations, options.integrators};
  const InterruptGuard interrupt;
  std::vector<BenchPoint> points;
  std::map<std::string, std::vector<std::string>> skipped;  // per scene, a line per mode it cannot run in
  if (sweepAsked) {
    Progress progress(err);
    points = measureSweep(scenes, grid, options.modes, options.repeats, hooks(interrupt, progress), skipped,
                          options.jobs > 0 ? options.jobs : availableThreads());
  }
  markParetoFronts(points);
  std::vector<SwitchPoint> switchPoints;
  if (options.switches && !interrupt.requested()) {
    Progress progress(err);
    switchPoints = measureSwitches(scenes, options.repeats, hooks(interrupt, progress));
  }
  std::vector<ScalePoint> scalePoints;
  if (!options.scale.empty() && !interrupt.requested()) {
    Progress progress(err);
    scalePoints = measureScale(options.scale, options.repeats, hooks(interrupt, progress));
  }
  std::vector<PilePoint> pilePoints;
  if (!options.piles.empty() && !interrupt.requested()) {
    Progress progress(err);
    pilePoints = measurePiles(options.piles, options.pileBudget, options.threads.value_or(availableThreads()),
                              hooks(interrupt, progress));
  }
  std::vector<HardPoint> hardPoints;
  if (options.hard && !interrupt.requested()) {
    try {
      Progress progress(err);
      hardPoints = measureHard((std::filesystem::path(options.scenarioDir) / "hard").string(), hooks(interrupt, progress));
    } catch (const ScenarioError& e) {
      for (const std::string& line : e.lines()) err << line << "\n";
      return kExitBadInput;
    }
  }

  std::vector<BaselinePoint> baselinePoints;
  if (options.baseline && !interrupt.requested()) {
    Progress progress(err);
    baselinePoints = measureBaseline(scenes, options.rates, options.repeats, hooks(interrupt, progress));
  }
  std::vector<LawPoint> lawPoints;
  if (options.laws && !interrupt.requested()) {
    Progress progress(err);
    lawPoints = measureLaws(options.rates, hooks(interrupt, progress), options.jobs > 0 ? options.jobs : availableThreads());
  }

  if (options.json) {
    out << nlohmann::json{{"sweep", toJson(sweepTable(points))},
                          {"laws", toJson(lawTable(lawPoints))},
                          {"baseline", toJson(baselineTable(baselinePoints))},
                          {"switches", toJson(switchTable(switchPoints))},
                          {"scale", toJson(scaleTable(scalePoints))},
                          {"growth_exponents", exponents(scalePoints)},
                          {"piles", toJson(pileTable(pilePoints))},
                          {"pile_exponents", pileExponents(pilePoints)},
                          {"hard", toJson(hardTable(hardPoints))}}
               .dump(2)
        << "\n";
  } else {
    const char* gap = "";
    if (sweepAsked) {
      for (std::size_t i = 0; i < scenes.size(); ++i) {
        ResultTable t = sweepTable(points, scenes[i].name(), scenes[i].analytic());
        for (const std::string& line : skipped[scenes[i].name()]) t.notes.push_back("(" + line + ")");
        out << (i ? "\n" : "") << toText(t);
      }
      gap = "\n";
    }
    if (!switchPoints.empty()) {
      out << gap << toText(switchTable(switchPoints));
      gap = "\n";
    }
    if (!scalePoints.empty()) {
      out << gap << toText(scaleTable(scalePoints));
      gap = "\n";
    }
    if (!options.piles.empty()) {
      ResultTable t = pileTable(pilePoints);
      if (pilePoints.size() < options.piles.size()) {
        t.notes.push_back("(left out after a pile stopped at the budget:" +
                          [&] {
                            std::string left;
                            for (std::size_t i = pilePoints.size(); i < options.piles.size(); ++i) {
                              left += " " + std::to_string(options.piles[i]);
                            }
                            return left;
                          }() + " bodies)");
      }
      out << gap << toText(t);
      gap = "\n";
    }
    if (!hardPoints.empty()) {
      out << gap << toText(hardTable(hardPoints));
      gap = "\n";
    }
    if (options.baseline) {
      ResultTable t = baselineTable(baselinePoints);
      for (const BenchScene& scene : scenes) {
        const auto measured = [&](const BaselinePoint& p) { return p.scene == scene.name(); };
        if (std::none_of(baselinePoints.begin(), baselinePoints.end(), measured)) {
          t.notes.push_back("(" + scene.name() + ": not measured, full physics refuses the scene)");
        }
      }
      out << gap << toText(t);
      gap = "\n";
    }
    if (!lawPoints.empty()) out << gap << toText(lawTable(lawPoints));
  }
  int status = kExitOk;
  if (options.frontFile && sweepAsked && !interrupt.requested()) {
    if (const std::string problem = AtomicFile::write(*options.frontFile, ToleranceFront::fromBench(points).toJson());
        !problem.empty()) {
      err << "tabletop bench: --write-front: " << problem << "\n";
      status = kExitFailure;
    }
  }
  if (options.outDir) {
    const std::filesystem::path dir(*options.outDir);
    std::string problem;
    const std::pair<const char*, ResultTable> sections[] = {
        {"bench.csv", sweepAsked ? sweepTable(points) : ResultTable{}},
        {"switches.csv", switchTable(switchPoints)},
        {"scale.csv", scaleTable(scalePoints)},
        {"piles.csv", pileTable(pilePoints)},
        {"hard.csv", hardTable(hardPoints)},
        {"laws.csv", lawTable(lawPoints)},
        {"baseline.csv", baselineTable(baselinePoints)}};
    for (const auto& [file, table] : sections) {
      if (problem.empty() && !table.rows.empty()) problem = AtomicFile::write((dir / file).string(), toCsv(table));
    }
    for (std::size_t i = 0; sweepAsked && problem.empty() && i < scenes.size(); ++i) {
      problem = writeGnuplotFile((dir / ("bench_" + scenes[i].name() + ".png")).string(),
                                 sweepPlotScript(points, scenes[i].name()), 900, 640);
    }
    if (!problem.empty()) {
      err << "tabletop bench: " << problem << "\n";
      status = kExitFailure;
    }
  }
  if (interrupt.requested()) {
    err << "tabletop bench: interrupted; the " << points.size() << " settings measured are above"
        << (options.outDir ? " and in " + *options.outDir : std::string()) << "\n";
    return kExitInterrupted;
  }
  return status;
}

}  // namespace tabletop
