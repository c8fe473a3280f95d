#include "app/BenchCommand.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/DataPaths.h"
#include "app/GnuplotFile.h"
#include "app/NumberOption.h"
#include "app/InterruptGuard.h"
#include "app/RunCommand.h"
#include "io/AtomicFile.h"
#include "scenario/ScenarioError.h"
#include "scenario/ScenarioLoader.h"
#include "measure/BenchRuns.h"
#include "measure/Benchmark.h"
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


// A bar on standard error, redrawn in place, when it is a terminal.
class Progress {
 public:
  explicit Progress(std::ostream& err) : err_(err), shown_(isatty(STDERR_FILENO)) {}
  void start(long total) { total_ = total; }
  void advance(const std::string& what) {
    ++done_;
    if (!shown_) return;
    const int width = 30, filled = static_cast<int>(width * done_ / std::max(1L, total_));
    err_ << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << done_ << "/" << total_
         << " " << what << "\033[K" << std::flush;
  }
  ~Progress() {
    if (shown_) err_ << "\r\033[K" << std::flush;
  }

 private:
  std::ostream& err_;
  long total_ = 0;
  long done_ = 0;
  bool shown_;
};

// What the measuring loops report to a terminal, and how Ctrl-C stops them.
MeasureHooks hooks(const InterruptGuard& interrupt, Progress& progress) {
  return {[&interrupt] { return interrupt.requested(); }, [&progress](long total) { progress.start(total); },
          [&progress](const std::string& done) { progress.advance(done); }};
}

std::string table(const std::vector<BenchPoint>& points, const std::string& scene, bool analytic) {
  std::ostringstream o;
  o << scene << "  (error against " << (analytic ? "the closed form" : "full physics at 4000 Hz, 50 iterations, trapezoid") << ")\n";
  o << "  " << padded("mode", 8) << padded("rate [Hz]", 11) << padded("iterations", 12) << padded("integrator", 12)
    << padded("cost [ms/s]", 13)
    << padded("spread", 9) << padded("error [mm]", 12) << "front\n";
  std::vector<BenchPoint> rows;
  for (const BenchPoint& p : points) {
    if (p.scene == scene) rows.push_back(p);
  }
  std::sort(rows.begin(), rows.end(), [](const BenchPoint& a, const BenchPoint& b) { return a.costMs < b.costMs; });
  for (const BenchPoint& p : rows) {
    o << "  " << padded(std::string(toString(p.mode)), 8) << padded(fixed(1.0 / p.timestep, 0), 11) << padded(std::to_string(p.iterations), 12)
      << padded(std::string(toString(p.integrator)), 12) << padded(fixed(p.costMs, 3), 13) << padded(fixed(100.0 * p.spread, 0) + "%", 9)
      << padded(p.complete ? fixed(1000.0 * p.error, 4) : std::string("diverged"), 12) << (p.front ? "*" : "")
      << "\n";
  }
  return o.str();
}

std::string csv(const std::vector<BenchPoint>& points) {
  std::ostringstream o;
  o << std::setprecision(9)
    << "scene,mode,rate_hz,timestep_s,iterations,integrator,cost_ms_per_s,spread,error_m,complete,front\n";
  for (const BenchPoint& p : points) {
    o << p.scene << "," << toString(p.mode) << "," << 1.0 / p.timestep << "," << p.timestep << "," << p.iterations << "," << toString(p.integrator)
      << "," << p.costMs << ","
      << p.spread << "," << p.error << "," << p.complete << "," << p.front << "\n";
  }
  return o.str();
}

// The curve a point belongs to: in bullet mode its integrator and
// iterations, otherwise its mode alone.
std::string family(const BenchPoint& p) {
  if (p.mode != SimulationMode::Bullet) return std::string(toString(p.mode));
  return std::string(toString(p.integrator)) + ", " + std::to_string(p.iterations) + " iterations";
}

// error [mm] against cost [ms per simulated second], log-log, one curve
// per family, the front circled.
std::string plotScript(const std::vector<BenchPoint>& points, const std::string& scene) {
  std::ostringstream g;
  g << std::setprecision(9);
  g << "set title " << gnuplotQuoted(scene + ": error against cost (Bullet, double)") << " noenhanced\n";
  g << "set logscale xy\nset grid\nset key top right\n";
  g << "set xlabel 'wall time per simulated second [ms]'\nset ylabel 'error [mm]'\n";
  std::vector<std::string> families;
  for (const BenchPoint& p : points) {
    if (p.scene == scene && std::find(families.begin(), families.end(), family(p)) == families.end()) {
      families.push_back(family(p));
    }
  }
  std::vector<std::string> curves;
  for (std::size_t f = 0; f < families.size(); ++f) {
    const std::string block = "$family" + std::to_string(f);
    g << block << " << EOD\n";
    for (const BenchPoint& p : points) {
      if (p.scene == scene && family(p) == families[f] && p.complete) {
        g << p.costMs << " " << std::max(1e-6, 1000.0 * p.error) << " " << 1.0 / p.timestep << "\n";
      }
    }
    g << "EOD\n";
    curves.push_back(block + " using 1:2 with linespoints title " + gnuplotQuoted(families[f]));
  }
  g << "$front << EOD\n";
  for (const BenchPoint& p : points) {
    if (p.scene == scene && p.front) g << p.costMs << " " << std::max(1e-6, 1000.0 * p.error) << "\n";
  }
  g << "EOD\n";
  curves.push_back("$front using 1:2 with points pt 6 ps 2.5 lc rgb 'black' title 'Pareto front'");
  g << "plot ";
  for (std::size_t i = 0; i < curves.size(); ++i) g << (i ? ", \\\n     " : "") << curves[i];
  g << "\n";
  return g.str();
}

}  // namespace

void addBenchOptions(CLI::App& command, BenchOptions& options) {
  command.add_option("SCENARIO", options.scenarios,
                     "Scenes to measure (default: scenarios/analytic/*.json and the report's examples)");
  command.add_option("--scenarios", options.scenarioDir, "Where the default scenes are (default: the shipped ones)");
  command.add_option("--cases", options.cases, "Only scenes whose name contains PATTERN");
  command.add_option("--out", options.outDir, "Write DIR/bench.csv and DIR/bench_SCENE.png (log-log plots)");
  command.add_option("--front", options.frontFile,
                     "Write the analytic cases' full-physics fronts to FILE, for run --tolerance "
                     "(the shipped one is data/tolerance_front.json)");
  command.add_flag("--json", options.json, "Print the measurements as JSON instead of tables");
  command.add_option("--repeats", options.repeats, "Timed runs per setting, after a warm-up (default 5)")
      ->check(CLI::Range(1, 1000));
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
  command.add_flag("--hard", options.hard,
                   "Run each hard case (SCENARIOS/hard) once at its own settings: cost, drift, penetration, "
                   "speed at rest, energy gain");
  enumOption(command.add_option("--modes", options.modes,
                                "Modes to sweep (default bullet,compat,rules; compat and rules at the scene's own "
                                "iterations)")
                 ->delimiter(','),
             kAllModes);
}

namespace {




std::string signedPercent(double ratio) {
  const double p = 100.0 * (ratio - 1.0);
  return (p >= 0 ? "+" : "") + fixed(p, 0) + "%";
}


std::string switchTable(const std::vector<SwitchPoint>& points) {
  std::ostringstream o;
  o << "Model switches (full physics, each scene at its own settings; cost and error as in the sweep)\n";
  o << "  " << padded("scene", 26) << padded("switch", 26) << padded("cost [ms/s]", 13) << padded("vs defaults", 13)
    << padded("error [mm]", 12) << "outcome\n";
  double base = 0.0;
  for (const SwitchPoint& p : points) {
    if (p.name == "defaults") base = p.costMs;
    o << "  " << padded(p.scene, 26) << padded(p.name, 26) << padded(fixed(p.costMs, 3), 13)
      << padded(p.name == "defaults" ? std::string("") : signedPercent(p.costMs / base), 13)
      << padded(p.complete ? fixed(1000.0 * p.error, 4) : std::string("diverged"), 12)
      << (p.name == "defaults" ? "" : p.sameState ? "bit-identical" : "differs") << "\n";
  }
  return o.str();
}

std::string switchCsv(const std::vector<SwitchPoint>& points) {
  std::ostringstream o;
  o << std::setprecision(9) << "scene,switch,cost_ms_per_s,spread,error_m,same_state,complete\n";
  for (const SwitchPoint& p : points) {
    o << p.scene << "," << p.name << "," << p.costMs << "," << p.spread << "," << p.error << "," << p.sameState << ","
      << p.complete << "\n";
  }
  return o.str();
}

std::string scaleCsv(const std::vector<ScalePoint>& points) {
  std::ostringstream o;
  o << std::setprecision(9) << "cubes,switch,ms_per_step,spread,difference_m,same_state,complete\n";
  for (const ScalePoint& p : points) {
    o << p.cubes << "," << p.name << "," << p.msPerStep << "," << p.spread << "," << p.difference << "," << p.sameState
      << "," << p.complete << "\n";
  }
  return o.str();
}




nlohmann::json hardJson(const HardPoint& p) {
  const StabilityReport& r = p.report;
  return {{"scene", p.scene}, {"timestep", p.settings.timestep}, {"iterations", p.settings.iterations},
          {"cost_ms_per_s", r.cost()}, {"worst_drift_m", r.worstDrift}, {"worst_penetration_m", r.worstPenetration},
          {"rest_speed_m_per_s", r.restSpeed}, {"energy_gain_j", r.energyGain}, {"energy_scale_j", r.energyScale},
          {"complete", r.complete}, {"failure", r.failure}};
}

std::string hardCsv(const std::vector<HardPoint>& points) {
  std::ostringstream o;
  o << std::setprecision(17)
    << "scene,timestep_s,iterations,cost_ms_per_s,worst_drift_m,worst_penetration_m,rest_speed_m_per_s,energy_gain_j,"
       "energy_scale_j,complete\n";
  for (const HardPoint& p : points) {
    const StabilityReport& r = p.report;
    o << p.scene << "," << p.settings.timestep << "," << p.settings.iterations << "," << r.cost() << ","
      << r.worstDrift << "," << r.worstPenetration << "," << r.restSpeed << "," << r.energyGain << ","
      << r.energyScale << "," << (r.complete ? 1 : 0) << "\n";
  }
  return o.str();
}

std::string hardTable(const std::vector<HardPoint>& points) {
  std::ostringstream o;
  o << "Hard cases (full physics, each at its own settings, one run)\n";
  std::size_t width = 5;
  for (const HardPoint& p : points) width = std::max(width, p.scene.size());
  o << "  " << std::left << std::setw(static_cast<int>(width)) << "scene"
    << "  rate [Hz]  iterations  cost [ms/s]  drift [mm]  penetration [mm]  rest [mm/s]  energy gain\n";
  for (const HardPoint& p : points) {
    const StabilityReport& r = p.report;
    o << "  " << std::setw(static_cast<int>(width)) << p.scene << "  " << std::setw(9)
      << fixed(1.0 / p.settings.timestep, 0) << "  " << std::setw(10) << p.settings.iterations << "  "
      << std::setw(11) << fixed(r.cost(), 2) << "  " << std::setw(10) << fixed(1e3 * r.worstDrift, 3) << "  "
      << std::setw(16) << fixed(1e3 * r.worstPenetration, 3) << "  " << std::setw(11) << fixed(1e3 * r.restSpeed, 4)
      << "  " << (r.energyScale > 0 ? fixed(100.0 * r.energyGain / r.energyScale, 3) + "%" : "0")
      << (r.complete ? "" : "  diverged: " + r.failure) << "\n";
  }
  return o.str();
}

std::string scaleTable(const std::vector<ScalePoint>& points) {
  std::ostringstream o;
  const Scenario any = CubeField::make(1);
  o << "Scale: the cube field (0.1 m cubes " << fixed(CubeField::kPitch, 2)
    << " m apart, every other column pushed into the next), " << fixed(CubeField::kDuration, 1) << " s at "
    << fixed(1.0 / any.settings.timestep, 0) << " Hz, " << any.settings.iterations << " iterations, "
    << toString(any.settings.integrator) << "\n";
  o << "  " << padded("cubes", 8) << padded("switch", 26) << padded("ms/step", 11) << padded("us/cube", 10)
    << padded("spread", 9) << padded("vs defaults", 13) << padded("moved [mm]", 12) << "outcome\n";
  double base = 0.0;
  for (const ScalePoint& p : points) {
    if (p.name == "defaults") base = p.msPerStep;
    o << "  " << padded(std::to_string(p.cubes), 8) << padded(p.name, 26) << padded(fixed(p.msPerStep, 3), 11)
      << padded(fixed(1000.0 * p.msPerStep / p.cubes, 2), 10) << padded(fixed(100.0 * p.spread, 0) + "%", 9)
      << padded(p.name == "defaults" ? std::string("") : signedPercent(p.msPerStep / base), 13)
      << padded(p.name == "defaults" ? std::string("") : fixed(1000.0 * p.difference, 4), 12)
      << (!p.complete ? "diverged" : p.name == "defaults" ? "" : p.sameState ? "bit-identical" : "differs") << "\n";
  }
  o << "  growth exponent k of time per step ~ cubes^k (least squares over the sizes):\n";
  for (const auto& [name, k] : exponents(points)) o << "    " << padded(name, 26) << fixed(k, 2) << "\n";
  return o.str();
}

}  // namespace

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

  const bool sweepAsked = options.sweep || (!options.switches && options.scale.empty() && !options.hard);
  const SweepGrid grid{options.rates, options.iterations, options.integrators};
  const InterruptGuard interrupt;
  std::vector<BenchPoint> points;
  std::map<std::string, std::vector<std::string>> skipped;  // per scene, a line per mode it cannot run in
  if (sweepAsked) {
    Progress progress(err);
    points = measureSweep(scenes, grid, options.modes, options.repeats, hooks(interrupt, progress), skipped);
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

  if (options.json) {
    nlohmann::json all = nlohmann::json::array();
    for (const BenchPoint& p : points) {
      all.push_back({{"scene", p.scene}, {"mode", toString(p.mode)}, {"timestep", p.timestep}, {"iterations", p.iterations},
                     {"integrator", toString(p.integrator)},
                     {"cost_ms_per_s", p.costMs}, {"spread", p.spread}, {"error_m", p.error},
                     {"complete", p.complete}, {"front", p.front}});
    }
    nlohmann::json switches = nlohmann::json::array();
    for (const SwitchPoint& p : switchPoints) {
      switches.push_back({{"scene", p.scene}, {"switch", p.name}, {"cost_ms_per_s", p.costMs}, {"spread", p.spread},
                          {"error_m", p.error}, {"same_state", p.sameState}, {"complete", p.complete}});
    }
    nlohmann::json scale = nlohmann::json::array();
    for (const ScalePoint& p : scalePoints) {
      scale.push_back({{"cubes", p.cubes}, {"switch", p.name}, {"ms_per_step", p.msPerStep}, {"spread", p.spread},
                       {"difference_m", p.difference}, {"same_state", p.sameState}, {"complete", p.complete}});
    }
    nlohmann::json hard = nlohmann::json::array();
    for (const HardPoint& p : hardPoints) hard.push_back(hardJson(p));
    out << nlohmann::json{{"sweep", all}, {"switches", switches}, {"scale", scale},
                          {"growth_exponents", exponents(scalePoints)}, {"hard", hard}}
               .dump(2)
        << "\n";
  } else {
    const char* gap = "";
    if (sweepAsked) {
      for (std::size_t i = 0; i < scenes.size(); ++i) {
        out << (i ? "\n" : "") << table(points, scenes[i].name(), scenes[i].analytic());
        for (const std::string& line : skipped[scenes[i].name()]) out << "  (" << line << ")\n";
      }
      gap = "\n";
    }
    if (!switchPoints.empty()) {
      out << gap << switchTable(switchPoints);
      gap = "\n";
    }
    if (!scalePoints.empty()) {
      out << gap << scaleTable(scalePoints);
      gap = "\n";
    }
    if (!hardPoints.empty()) out << gap << hardTable(hardPoints);
  }
  int status = kExitOk;
  if (options.frontFile && sweepAsked && !interrupt.requested()) {
    if (const std::string problem = AtomicFile::write(*options.frontFile, ToleranceFront::fromBench(points).toJson());
        !problem.empty()) {
      err << "tabletop bench: --front: " << problem << "\n";
      status = kExitFailure;
    }
  }
  if (options.outDir) {
    const std::filesystem::path dir(*options.outDir);
    std::string problem;
    if (sweepAsked) problem = AtomicFile::write((dir / "bench.csv").string(), csv(points));
    if (problem.empty() && !switchPoints.empty()) {
      problem = AtomicFile::write((dir / "switches.csv").string(), switchCsv(switchPoints));
    }
    if (problem.empty() && !scalePoints.empty()) {
      problem = AtomicFile::write((dir / "scale.csv").string(), scaleCsv(scalePoints));
    }
    if (problem.empty() && !hardPoints.empty()) problem = AtomicFile::write((dir / "hard.csv").string(), hardCsv(hardPoints));
    for (std::size_t i = 0; sweepAsked && problem.empty() && i < scenes.size(); ++i) {
      problem = writeGnuplotFile((dir / ("bench_" + scenes[i].name() + ".png")).string(),
                                 plotScript(points, scenes[i].name()), 900, 640);
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
