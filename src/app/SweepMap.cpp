#include "app/SweepMap.h"

#include <algorithm>
#include <map>
#include <sstream>

#include "app/GnuplotFile.h"

namespace tabletop {
namespace {

// Agreement in green; the reasons in the other Okabe and Ito colours, in
// order of how many runs each explains; runs that did not run in grey.
constexpr const char* kAgrees = "#009E73";
constexpr const char* kReasonColours[] = {"#D55E00", "#0072B2", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"};
constexpr const char* kNotRun = "#999999";

}  // namespace

std::string sweepMapScript(const SweepSpec& spec, const std::vector<SweepRow>& rows, std::string& problem) {
  const std::vector<std::string> columns = sweepColumns(spec);
  // The mode drawn: the last one compared with the rules (bullet if it ran).
  std::string mode;
  for (SimulationMode m : spec.modes) {
    if (std::find(columns.begin(), columns.end(), std::string(toString(m)) + ".reason") != columns.end())
      mode = toString(m);
  }
  if (spec.parameters.size() < 2)
    problem = "the map needs two varied parameters, the spec has " + std::to_string(spec.parameters.size());
  else if (mode.empty())
    problem = "the map needs the rules and another mode, recording \"distance\"";
  if (!problem.empty()) return "";
  const auto column = [&columns](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  const std::size_t agrees = column(mode + ".agrees"), reason = column(mode + ".reason"), failed = column("problem");
  // Each run's category: "agrees", its first reason, or "did not run".
  std::map<std::string, std::vector<std::pair<double, double>>> points;
  for (const SweepRow& row : rows) {
    if (!row.at(1).is_number() || !row.at(2).is_number()) {
      problem =
          "the map needs numeric parameters; " + spec.parameters[0].name + " or " + spec.parameters[1].name + " is not";
      return "";
    }
    std::string category = "did not run";
    if (row.at(failed) == "" && row.at(agrees).is_boolean()) {
      category = row.at(agrees).get<bool>() ? "agrees" : row.at(reason).get<std::string>();
    }
    points[category].emplace_back(row[1].get<double>(), row[2].get<double>());
  }
  std::vector<std::string> order;
  for (const auto& [category, list] : points) {
    if (category != "agrees" && category != "did not run") order.push_back(category);
  }
  std::stable_sort(order.begin(), order.end(), [&points](const std::string& a, const std::string& b) {
    return points[a].size() > points[b].size();
  });
  if (points.count("agrees")) order.insert(order.begin(), "agrees");
  if (points.count("did not run")) order.push_back("did not run");

  std::ostringstream g;
  g.precision(17);
  g << "set title "
    << gnuplotQuoted(spec.name + ": " + mode + " against the rules, " + std::to_string(rows.size()) + " runs")
    << " noenhanced\n";
  g << "set xlabel " << gnuplotQuoted(spec.parameters[0].name) << " noenhanced\n";
  g << "set ylabel " << gnuplotQuoted(spec.parameters[1].name) << " noenhanced\n";
  g << "set key outside right top noenhanced title " << gnuplotQuoted("first reason")
    << "\nset grid\nset offsets graph 0.03, graph 0.03, graph 0.03, graph 0.03\n";
  for (std::size_t k = 0; k < order.size(); ++k) {
    g << "$d" << k << " << EOD\n";
    for (const auto& [x, y] : points[order[k]]) g << x << " " << y << "\n";
    g << "EOD\n";
  }
  g << "plot ";
  std::size_t reasons = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::string& c = order[k];
    const std::string colour = c == "agrees" ? kAgrees
                               : c == "did not run"
                                   ? kNotRun
                                   : kReasonColours[reasons++ % (sizeof kReasonColours / sizeof *kReasonColours)];
    g << (k ? ", \\\n     " : "") << "$d" << k << " with points pt 5 ps 1.6 lc rgb '" << colour << "' title "
      << gnuplotQuoted(c + " (" + std::to_string(points[c].size()) + ")");
  }
  g << "\n";
  return g.str();
}

std::string writeSweepMap(const SweepSpec& spec, const std::vector<SweepRow>& rows, const std::string& path) {
  std::string problem;
  const std::string script = sweepMapScript(spec, rows, problem);
  if (!problem.empty()) return "--plot: " + problem;
  problem = writeGnuplotFile(path, script, 1000, 700);
  return problem.empty() ? problem : "--plot: " + problem;
}

}  // namespace tabletop
