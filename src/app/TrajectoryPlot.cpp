#include "app/TrajectoryPlot.h"

#include <algorithm>
#include <sstream>

#include "app/GnuplotFile.h"

namespace tabletop {
namespace {

// One colour and dash per mode, like kAllModes: rules, compat, bullet.
constexpr const char* kModeStyle[3] = {"lc rgb '#000000' dt 2 lw 1.5", "lc rgb '#1f5fd0' lw 4",
                                       "lc rgb '#d03020' lw 2"};

const auto quoted = gnuplotQuoted;

}  // namespace

std::string writeTrajectoryPlot(const Comparison& c, const TableSpec& table, const std::string& path) {
  std::ostringstream g;
  g << "set title " << quoted(c.scenario + ": top view, rules (dashed), compat, bullet") << " noenhanced\n";
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
  const double margin = 0.05 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  g << "set size ratio -1\nset grid\nset key below noenhanced\n";
  g << "set xrange [" << lo[0] - margin << ":" << hi[0] + margin << "]\n";
  g << "set yrange [" << hi[1] + margin << ":" << lo[1] - margin << "]\n";  // +z down the page
  g << "set object 1 rect from " << x0 << "," << z0 << " to " << x1 << "," << z1
    << " fc rgb '#e8d8c0' fs solid 0.5 border lc rgb '#966432' behind\n";
  // Inline data blocks: one per entity and mode.
  int block = 0;
  for (const EntityComparison& e : c.entities) {
    for (std::size_t m = 0; m < 3; ++m) {
      g << "$d" << block++ << " << EOD\n";
      for (const Vec3& p : e.modes[m].trajectory.points) g << p.x << " " << p.z << "\n";
      g << "EOD\n";
    }
  }
  int label = 2;
  for (const EntityComparison& e : c.entities) {
    g << "set label " << label++ << " " << quoted(e.name) << " at " << e.start.x << "," << e.start.z
      << " offset 0.5,0.5 noenhanced\n";
  }
  // Bullet first, the rules last, so the dashed reference stays on top.
  g << "plot ";
  bool first = true;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t m = 2 - k;
    for (std::size_t i = 0; i < c.entities.size(); ++i) {
      const EntityComparison& e = c.entities[i];
      const std::string title = e.name + " " + std::string(toString(kAllModes[m])) + ": " + e.modes[m].verdict;
      g << (first ? "" : ", \\\n     ") << "$d" << 3 * i + m << " with lines " << kModeStyle[m] << " title "
        << quoted(title);
      first = false;
    }
  }
  const std::string problem = writeGnuplotFile(path, g.str(), 1000, 760);
  return problem.empty() ? problem : "--plot: " + problem;
}

}  // namespace tabletop
