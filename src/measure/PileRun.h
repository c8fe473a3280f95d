#pragma once

#include <map>
#include <string>
#include <vector>

#include "measure/BenchRuns.h"
#include "measure/SettledWatch.h"

namespace tabletop {

/// One engine's run of a pile (Pile): its cost and how it settled.
struct PileSide {
  double costMsPerSecond = 0;  ///< wall time per simulated second, ms
  double simulated = 0;        ///< s actually run
  Settled settled;             ///< over the window after the drop
  std::string note;            ///< why the run stopped early, if it did
  /// tabletop's: the mean number of parts taken per step of the scene's
  /// rate (each runs the collision and the solve for the whole pile), the
  /// parts of its equal sub-steps (World::substeps) together; 1 for Bullet.
  double partsPerStep = 1;
  long largestIsland = 0;  ///< tabletop's: the most bodies one island held
};

/// A pile of `bodies` in tabletop and in Bullet's own pipeline (PlainBullet).
struct PilePoint {
  int bodies = 0;
  PileSide tabletop, bullet;
};

/// Runs the pile of each size once in tabletop (timed as it runs) and in
/// Bullet's own pipeline (a watched warm-up, then one timed run). A
/// tabletop run stops once its stepping has taken `budgetSeconds` of wall
/// time: its cost is then that of the part it ran, its window unmeasured,
/// and the larger sizes are left out (a pile costs more with every body).
std::vector<PilePoint> measurePiles(const std::vector<int>& sizes, double budgetSeconds, const MeasureHooks& hooks);

/// The growth exponent of tabletop's and Bullet's cost over the piles
/// ("tabletop", "bullet").
std::map<std::string, double> pileExponents(const std::vector<PilePoint>& points);

}  // namespace tabletop
