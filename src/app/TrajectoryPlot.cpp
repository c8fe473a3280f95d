#include "app/TrajectoryPlot.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <sstream>

#include "app/GnuplotFile.h"

namespace tabletop {
namespace {

// One colour per entity, apart in print and for colour-blind readers
// (Okabe and Ito); one line style and end marker per mode, as kAllModes:
// rules, compat, bullet.
constexpr const char* kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000"};
constexpr const char* kModeLine[3] = {"dt 2 lw 2", "dt 3 lw 3", "dt 1 lw 2"};
constexpr int kModeEnd[3] = {6, 4, 7};  // open circle, open square, filled circle
// Labels closer than this, as a fraction of the view, are moved apart.
constexpr double kLabelRoom = 0.04;

const auto quoted = gnuplotQuoted;

std::string colour(std::size_t entity) { return kColours[entity % (sizeof kColours / sizeof *kColours)]; }

}  // namespace

std::string trajectoryPlotScript(const Comparison& c, const TableSpec& table) {
  std::ostringstream g;
  g << "set title " << quoted(c.scenario + ": top view; colour per entity, line per mode") << " noenhanced\n";
  g << "set xlabel 'x [m]'\nset ylabel 'z [m] (towards the viewer, down the page)'\n";
  const double x0 = table.centreX - 0.5 * table.width, x1 = table.centreX + 0.5 * table.width;
  const double z0 = table.centreZ - 0.5 * table.depth, z1 = table.centreZ + 0.5 * table.depth;
  // The view holds the table and every path, with a margin.
  double lo[2] = {x0, z0}, hi[2] = {x1, z1};
  for (const EntityComparison& e : c.entities) {
    for (const ModeOutcome& o : e.modes) {
      for (const Vec3& p : o.trajectory.points) {
        lo[0] = std::min(lo[0], p.x), hi[0] = std::max(hi[0], p.x);
        lo[1] = std::min(lo[1], p.z), hi[1] = std::max(hi[1], p.z);
      }
    }
  }
  const double span = std::max(hi[0] - lo[0], hi[1] - lo[1]), margin = 0.05 * span;
  g << "set size ratio -1\nset grid\nset key outside right top noenhanced\n";
  g << "set xrange [" << lo[0] - margin << ":" << hi[0] + margin << "]\n";
  g << "set yrange [" << hi[1] + margin << ":" << lo[1] - margin << "]\n";  // +z down the page
  g << "set object 1 rect from " << x0 << "," << z0 << " to " << x1 << "," << z1
    << " fc rgb '#e8d8c0' fs solid 0.5 border lc rgb '#966432' behind\n";
  // Inline data blocks: one per entity and mode.
  for (std::size_t i = 0; i < c.entities.size(); ++i) {
    for (std::size_t m = 0; m < 3; ++m) {
      g << "$d" << 3 * i + m << " << EOD\n";
      for (const Vec3& p : c.entities[i].modes[m].trajectory.points) g << p.x << " " << p.z << "\n";
      g << "EOD\n";
    }
  }
  // Names at the starts, each moved down the page below any placed near it.
  std::vector<std::pair<double, double>> placed;
  for (std::size_t i = 0; i < c.entities.size(); ++i) {
    const EntityComparison& e = c.entities[i];
    double x = e.start.x, z = e.start.z;
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [px, pz] : placed) {
        if (std::abs(px - x) < kLabelRoom * span * 2 && std::abs(pz - z) < kLabelRoom * span) z += kLabelRoom * span, moved = true;
      }
    }
    placed.emplace_back(x, z);
    g << "set label " << i + 2 << " " << quoted(e.name) << " at " << x << "," << z << " offset 0.8,0.8 tc rgb '"
      << colour(i) << "' noenhanced\n";
  }
  // Bullet first, the rules last, so the dashed reference stays on top;
  // a mark at each start and at each mode's end; the legend says which
  // colour is which entity and which line which mode.
  g << "plot ";
  bool first = true;
  const auto next = [&] {
    const char* sep = first ? "" : ", \\\n     ";
    first = false;
    return sep;
  };
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t m = 2 - k;
    for (std::size_t i = 0; i < c.entities.size(); ++i) {
      const std::string data = "$d" + std::to_string(3 * i + m);
      g << next() << data << " with lines " << kModeLine[m] << " lc rgb '" << colour(i) << "' notitle";
      g << next() << data << " every ::0::0 with points pt 2 ps 1.5 lc rgb '" << colour(i) << "' notitle";
      g << next() << data << " every ::" << c.entities[i].modes[m].trajectory.points.size() - 1
        << " with points pt " << kModeEnd[m] << " ps 1.8 lc rgb '" << colour(i) << "' notitle";
    }
  }
  for (std::size_t i = 0; i < c.entities.size(); ++i) {
    g << next() << "keyentry with lines lw 4 lc rgb '" << colour(i) << "' title " << quoted(c.entities[i].name);
  }
  for (std::size_t m = 0; m < 3; ++m) {
    g << next() << "keyentry with linespoints " << kModeLine[m] << " pt " << kModeEnd[m] << " lc rgb '#404040' title "
      << quoted(std::string(toString(kAllModes[m])) + " (end marked)");
  }
  g << next() << "keyentry with points pt 2 lc rgb '#404040' title 'start'\n";
  return g.str();
}

std::string writeTrajectoryPlot(const Comparison& c, const TableSpec& table, const std::string& path) {
  const std::string problem = writeGnuplotFile(path, trajectoryPlotScript(c, table), 1000, 760);
  return problem.empty() ? problem : "--plot: " + problem;
}

}  // namespace tabletop
