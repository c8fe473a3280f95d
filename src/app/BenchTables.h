#pragma once

#include <string>
#include <vector>

#include "io/ResultTable.h"
#include "measure/BenchRuns.h"
#include "measure/Benchmark.h"
#include "measure/PileRun.h"

namespace tabletop {

/// bench's sections as plain rows (ResultTable), each written as a text
/// table, CSV or JSON by the same three writers.

/// The sweep's points; with `scene`, that scene's alone, cheapest first,
/// titled with what its error is measured against.
ResultTable sweepTable(const std::vector<BenchPoint>& points);
ResultTable sweepTable(const std::vector<BenchPoint>& points, const std::string& scene, bool analytic);

/// The model switches, each against its scene's defaults.
ResultTable switchTable(const std::vector<SwitchPoint>& points);

/// The cube field's sizes and switches, with the growth exponents as notes.
ResultTable scaleTable(const std::vector<ScalePoint>& points);

/// The piles of each size, tabletop against Bullet, with the growth
/// exponents as notes.
ResultTable pileTable(const std::vector<PilePoint>& points);

/// The hard cases, each run once.
ResultTable hardTable(const std::vector<HardPoint>& points);

/// Each scene's cost at each rate against Bullet's own default pipeline.
ResultTable baselineTable(const std::vector<BaselinePoint>& points);

/// A gnuplot script: error [mm] against cost [ms per simulated second] of
/// one scene, log-log, one curve per family (mode, or integrator and
/// iterations in full physics), the front circled.
std::string sweepPlotScript(const std::vector<BenchPoint>& points, const std::string& scene);

}  // namespace tabletop
