#include "app/BenchTables.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "app/GnuplotFile.h"
#include "core/Text.h"
#include "scenes/CubeField.h"
#include "scenes/Pile.h"

namespace tabletop {
namespace {

using Column = ResultTable::Column;
using Cell = ResultTable::Cell;

std::string signedPercent(double ratio) {
  const double p = 100.0 * (ratio - 1.0);
  return (p >= 0 ? "+" : "") + fixed(p, 0) + "%";
}

Cell percent(double fraction) { return cell(fraction, fixed(100.0 * fraction, 0) + "%"); }

// An error in metres, shown in millimetres, or "diverged".
Cell errorCell(double metres, bool complete, int digits = 4) {
  return cell(metres, complete ? fixed(1000.0 * metres, digits) : std::string("diverged"));
}

Cell flag(bool value, const std::string& shown) { return cell(value, shown); }

std::string name(SimulationMode m) { return std::string(toString(m)); }
std::string name(Integrator i) { return std::string(toString(i)); }

}  // namespace

ResultTable sweepTable(const std::vector<BenchPoint>& points) {
  ResultTable t;
  t.columns = {{"scene", ""},
               {"mode", "mode"},
               {"rate_hz", "rate [Hz]"},
               {"timestep_s", ""},
               {"iterations", "iterations"},
               {"integrator", "integrator"},
               {"cost_ms_per_s", "cost [ms/s]"},
               {"spread", "spread"},
               {"error_m", "error [mm]"},
               {"complete", ""},
               {"front", "front"}};
  for (const BenchPoint& p : points) {
    t.rows.push_back({cell(p.scene), cell(name(p.mode)), cell(1.0 / p.timestep, 0), cell(p.timestep, 6),
                      cell(p.iterations, std::to_string(p.iterations)), cell(name(p.integrator)), cell(p.costMs, 3),
                      percent(p.spread), errorCell(p.error, p.complete), flag(p.complete, ""),
                      flag(p.front, p.front ? "*" : "")});
  }
  return t;
}

ResultTable sweepTable(const std::vector<BenchPoint>& points, const std::string& scene, bool analytic) {
  std::vector<BenchPoint> rows;
  for (const BenchPoint& p : points) {
    if (p.scene == scene) rows.push_back(p);
  }
  std::stable_sort(rows.begin(), rows.end(), [](const BenchPoint& a, const BenchPoint& b) { return a.costMs < b.costMs; });
  ResultTable t = sweepTable(rows);
  t.title = scene + "  (error against " +
            (analytic ? "the closed form" : "full physics at 4000 Hz, 50 iterations, trapezoid") + ")";
  return t;
}

ResultTable switchTable(const std::vector<SwitchPoint>& points) {
  ResultTable t;
  t.title = "Model switches (full physics, each scene at its own settings; cost and error as in the sweep)";
  t.columns = {{"scene", "scene"},         {"switch", "switch"},        {"cost_ms_per_s", "cost [ms/s]"},
               {"spread", ""},             {"", "vs defaults"},         {"error_m", "error [mm]"},
               {"same_state", "outcome"},  {"complete", ""}};
  double base = 0.0;
  for (const SwitchPoint& p : points) {
    const bool defaults = p.name == "defaults";
    if (defaults) base = p.costMs;
    t.rows.push_back({cell(p.scene), cell(p.name), cell(p.costMs, 3), percent(p.spread),
                      cell(nullptr, defaults ? "" : signedPercent(p.costMs / base)), errorCell(p.error, p.complete),
                      flag(p.sameState, defaults ? "" : p.sameState ? "bit-identical" : "differs"),
                      flag(p.complete, "")});
  }
  return t;
}

ResultTable baselineTable(const std::vector<BaselinePoint>& points) {
  ResultTable t;
  t.title = "Against Bullet's own default pipeline (the same scene and rate, as long as tabletop's run; its "
            "defaults otherwise: 10 iterations, warm start 0.85, Euler)";
  t.columns = {{"scene", "scene"},
               {"rate_hz", "rate [Hz]"},
               {"tabletop_ms_per_s", "tabletop [ms/s]"},
               {"bullet_ms_per_s", "Bullet [ms/s]"},
               {"ratio", "ratio"},
               {"simulated_s", "simulated [s]"}};
  for (const BaselinePoint& p : points) {
    t.rows.push_back({cell(p.scene), cell(p.rate, 0), cell(p.tabletopMs, 3), cell(p.bulletMs, 3),
                      cell(p.tabletopMs / p.bulletMs, 2), cell(p.simulated, 3)});
  }
  return t;
}

ResultTable scaleTable(const std::vector<ScalePoint>& points) {
  ResultTable t;
  const Scenario any = CubeField::make(1);
  t.title = "Scale: the cube field (0.1 m cubes " + fixed(CubeField::kPitch, 2) +
            " m apart, every other column pushed into the next), " + fixed(CubeField::kDuration, 1) + " s at " +
            fixed(1.0 / any.settings.timestep, 0) + " Hz, " + std::to_string(any.settings.iterations) +
            " iterations, " + name(any.settings.integrator);
  t.columns = {{"cubes", "cubes"},         {"switch", "switch"},           {"ms_per_step", "ms/step"},
               {"", "us/cube"},            {"spread", "spread"},           {"", "vs defaults"},
               {"difference_m", "moved [mm]"}, {"same_state", "outcome"}, {"complete", ""}};
  double base = 0.0;
  for (const ScalePoint& p : points) {
    const bool defaults = p.name == "defaults";
    if (defaults) base = p.msPerStep;
    t.rows.push_back({cell(p.cubes, std::to_string(p.cubes)), cell(p.name), cell(p.msPerStep, 3),
                      cell(nullptr, fixed(1000.0 * p.msPerStep / p.cubes, 2)), percent(p.spread),
                      cell(nullptr, defaults ? "" : signedPercent(p.msPerStep / base)),
                      cell(p.difference, defaults ? "" : fixed(1000.0 * p.difference, 4)),
                      flag(p.sameState, !p.complete ? "diverged" : defaults ? "" : p.sameState ? "bit-identical" : "differs"),
                      flag(p.complete, "")});
  }
  t.notes.push_back("growth exponent k of time per step ~ cubes^k (least squares over the sizes):");
  for (const auto& [switchName, k] : exponents(points)) t.notes.push_back("  " + padded(switchName, 26) + fixed(k, 2));
  return t;
}

ResultTable pileTable(const std::vector<PilePoint>& points) {
  ResultTable t;
  t.title = "Piles: N mixed bodies (cubes, spheres, boxes, standing cylinders) dropped at once from a grid " +
            fixed(100.0 * Pile::kGap, 0) + " cm apart, " + fixed(Pile::kSettle + Pile::kWindow, 1) + " s at " +
            fixed(Pile::kRate, 0) + " Hz; settled: over the last " + fixed(Pile::kWindow, 1) +
            " s, against Bullet's own pipeline";
  t.columns = {{"bodies", "bodies"},
               {"tabletop_ms_per_s", "tabletop [ms/s]"},
               {"bullet_ms_per_s", "Bullet [ms/s]"},
               {"ratio", "ratio"},
               {"threads", "threads"},
               {"threaded_ms_per_s", "on threads [ms/s]"},
               {"threaded_ratio", "ratio"},
               {"threaded_same_state", "same"},
               {"tabletop_drift_m", "drift [mm]"},
               {"bullet_drift_m", "Bullet drift [mm]"},
               {"tabletop_penetration_m", "deepest [mm]"},
               {"bullet_penetration_m", "Bullet deepest [mm]"},
               {"tabletop_energy_gain_j", "gain [J]"},
               {"bullet_energy_gain_j", "Bullet gain [J]"},
               {"simulated_s", "simulated [s]"},
               {"parts_per_step", "parts/step"},
               {"largest_island", "largest island"},
               {"note", "note"}};
  // A settled figure, or "-" when the window was not reached.
  const auto settled = [](const PileSide& s, double value, double scale, int digits) {
    return s.settled.measured ? cell(value, fixed(scale * value, digits)) : cell(nullptr, "-");
  };
  for (const PilePoint& p : points) {
    const PileSide &a = p.tabletop, &b = p.bullet, &c = p.threaded;
    const bool threaded = p.threads > 1;
    t.rows.push_back({cell(p.bodies, std::to_string(p.bodies)), cell(a.costMsPerSecond, 1),
                      cell(b.costMsPerSecond, 1), cell(a.costMsPerSecond / b.costMsPerSecond, 2),
                      cell(p.threads, std::to_string(p.threads)),
                      threaded ? cell(c.costMsPerSecond, 1) : cell(nullptr, "-"),
                      threaded ? cell(c.costMsPerSecond / b.costMsPerSecond, 2) : cell(nullptr, "-"),
                      threaded ? flag(c.hash == a.hash && c.simulated == a.simulated, c.hash == a.hash ? "yes" : "NO")
                               : cell(nullptr, "-"),
                      settled(a, a.settled.drift, 1e3, 3), settled(b, b.settled.drift, 1e3, 3),
                      settled(a, a.settled.penetration, 1e3, 3), settled(b, b.settled.penetration, 1e3, 3),
                      settled(a, a.settled.energyGain, 1.0, 4), settled(b, b.settled.energyGain, 1.0, 4),
                      cell(a.simulated, 3), cell(a.partsPerStep, 2),
                      cell(a.largestIsland, std::to_string(a.largestIsland)), cell(a.note)});
  }
  t.notes.push_back("growth exponent k of cost ~ bodies^k (least squares over the sizes):");
  for (const auto& [engine, k] : pileExponents(points)) t.notes.push_back("  " + padded(engine, 26) + fixed(k, 2));
  return t;
}

ResultTable hardTable(const std::vector<HardPoint>& points) {
  ResultTable t;
  t.title = "Hard cases, one run each at the scene's own settings (the solver chosen per island unless the scene "
            "names one), then with " + std::to_string(kHardSweeps) +
            " sweeps of sequential impulses, then in Bullet's own default pipeline at the same step; a case "
            "resting within a peer's drift (MuJoCo's defaults on the ten-cube stack at 120 Hz) also at the lowest "
            "rate that holds it";
  t.columns = {{"scene", "scene"},
               {"timestep_s", ""},
               {"", "rate [Hz]"},
               {"iterations", ""},
               {"islands_direct", "exact"},
               {"islands_guessed", "guessed"},
               {"islands_swept", "swept"},
               {"islands_long_swept", "long"},
               {"islands_fallen_back", "fell back"},
               {"cost_ms_per_s", "cost [ms/s]"},
               {"worst_drift_m", "drift [mm]"},
               {"worst_penetration_m", "penetration [mm]"},
               {"rest_speed_m_per_s", "rest [mm/s]"},
               {"energy_gain_j", "energy gain"},
               {"energy_scale_j", ""},
               {"complete", ""},
               {"failure", "outcome"},
               {"sweeps_cost_ms_per_s", "sweeps: cost"},
               {"sweeps_worst_drift_m", "drift [mm]"},
               {"sweeps_worst_penetration_m", "penetration [mm]"},
               {"sweeps_complete", ""},
               {"bullet_cost_ms_per_s", "Bullet: cost"},
               {"bullet_worst_drift_m", "drift [mm]"},
               {"peer_drift_m", ""},
               {"peer_drift_rate_hz", "at " + fixed(1e3 * kPeerDrift, 1) + " mm: rate [Hz]"},
               {"peer_drift_cost_ms_per_s", "cost"},
               {"peer_drift_worst_drift_m", "drift [mm]"}};
  const auto millimetres = [](double metres) { return errorCell(metres, true, 3); };
  for (const HardPoint& p : points) {
    const StabilityReport& r = p.report;
    const StabilityReport& w = p.sweeps;
    const DriftMatch& m = p.atPeerDrift;
    // A case that does not rest within the peer's drift has no such rate.
    const auto matchCell = [&m](double value, const std::string& shown) {
      return m.rate > 0 ? cell(value, shown) : cell(nullptr, "-");
    };
    t.rows.push_back(
        {cell(p.scene), cell(p.settings.timestep, 6), cell(nullptr, fixed(1.0 / p.settings.timestep, 0)),
         cell(p.settings.iterations, ""), cell(r.solverUse.direct, std::to_string(r.solverUse.direct)),
         cell(r.solverUse.guessed, std::to_string(r.solverUse.guessed)),
         cell(r.solverUse.swept, std::to_string(r.solverUse.swept)),
         cell(r.solverUse.longSwept, std::to_string(r.solverUse.longSwept)),
         cell(r.solverUse.fallbacks, std::to_string(r.solverUse.fallbacks)),
         cell(r.cost(), 2), millimetres(r.worstDrift), millimetres(r.worstPenetration),
         cell(r.restSpeed, fixed(1e3 * r.restSpeed, 4)),
         cell(r.energyGain, r.energyScale > 0 ? fixed(100.0 * r.energyGain / r.energyScale, 3) + "%" : "0"),
         cell(r.energyScale, ""), flag(r.complete, ""), cell(r.failure, r.complete ? "" : "diverged: " + r.failure),
         cell(w.cost(), 2), errorCell(w.worstDrift, w.complete, 3),
         millimetres(w.worstPenetration), flag(w.complete, ""), cell(p.plain.costMsPerSecond, 2),
         millimetres(p.plain.worstDrift), cell(kPeerDrift, ""), matchCell(m.rate, fixed(m.rate, 0)),
         matchCell(m.report.cost(), fixed(m.report.cost(), 2)),
         matchCell(m.report.worstDrift, fixed(1e3 * m.report.worstDrift, 3))});
  }
  return t;
}

std::string sweepPlotScript(const std::vector<BenchPoint>& points, const std::string& scene) {
  // Errors below this (mm) are drawn on it, a labelled line: exact.
  constexpr double kFloorMm = 1e-6;
  // Colours that stay apart in print and for colour-blind readers (Okabe and Ito).
  static const char* const kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};
  // The curve a point belongs to: in bullet mode its integrator and
  // iterations, otherwise its mode alone.
  const auto family = [](const BenchPoint& p) {
    if (p.mode != SimulationMode::Bullet) return name(p.mode);
    return name(p.integrator) + ", " + std::to_string(p.iterations) + " iterations";
  };
  const auto shown = [&scene](const BenchPoint& p) { return p.scene == scene && p.complete && !p.reference; };
  std::ostringstream g;
  g << std::setprecision(9);
  g << "set title " << gnuplotQuoted(scene + ": error against cost (Bullet, double)") << " noenhanced\n";
  g << "set logscale xy\nset grid\nset key outside right top noenhanced\n";
  g << "set format x '10^{%L}'\nset format y '10^{%L}'\n";
  g << "set xlabel 'wall time per simulated second [ms]'\nset ylabel 'error [mm]'\n";
  g << "set arrow from graph 0, first " << kFloorMm << " to graph 1, first " << kFloorMm
    << " nohead dt 3 lc rgb '#808080'\n";
  g << "set label 'exact (below 10^{-6} mm)' at graph 0.02, first " << 1.6 * kFloorMm << " tc rgb '#606060'\n";
  std::vector<std::string> families;
  for (const BenchPoint& p : points) {
    if (shown(p) && std::find(families.begin(), families.end(), family(p)) == families.end()) {
      families.push_back(family(p));
    }
  }
  std::vector<std::string> curves;
  for (std::size_t f = 0; f < families.size(); ++f) {
    const std::string block = "$family" + std::to_string(f);
    g << block << " << EOD\n";
    for (const BenchPoint& p : points) {
      if (shown(p) && family(p) == families[f]) {
        g << p.costMs << " " << std::max(kFloorMm, 1000.0 * p.error) << " " << 1.0 / p.timestep << "\n";
      }
    }
    g << "EOD\n";
    const std::string style = std::string("lc rgb '") + kColours[f % 7] + "' pt " + std::to_string(5 + 2 * (f % 4)) +
                              " dt " + std::to_string(1 + f / 7);
    curves.push_back(block + " using 1:2 with linespoints lw 2 " + style + " title " + gnuplotQuoted(families[f]));
    // Each point's rate beside it.
    curves.push_back(block + " using 1:2:(sprintf('%g Hz', $3)) with labels offset 0.6,0.6 left font ',8' tc rgb '" +
                     std::string(kColours[f % 7]) + "' notitle");
  }
  g << "$front << EOD\n";
  for (const BenchPoint& p : points) {
    if (shown(p) && p.front) g << p.costMs << " " << std::max(kFloorMm, 1000.0 * p.error) << "\n";
  }
  g << "EOD\n";
  curves.push_back("$front using 1:2 with points pt 6 ps 2.5 lc rgb 'black' title 'Pareto front'");
  g << "plot ";
  for (std::size_t i = 0; i < curves.size(); ++i) g << (i ? ", \\\n     " : "") << curves[i];
  g << "\n";
  return g.str();
}

}  // namespace tabletop
