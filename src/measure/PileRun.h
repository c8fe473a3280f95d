#pragma once

#include <cstdint>
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
  std::uint64_t hash = 0;  ///< tabletop's: the state where it stopped (stateHash)
};

/// A pile of `bodies` in tabletop and in Bullet's own pipeline (PlainBullet).
struct PilePoint {
  int bodies = 0;
  PileSide tabletop, bullet;
  int threads = 1;    ///< tabletop's second run's threads (1: none run)
  PileSide threaded;  ///< tabletop's run on `threads` threads
};

/// Runs the pile of each size once in tabletop on one thread (timed as it
/// runs), again on `threads` if more than one, and in Bullet's own
/// pipeline (a watched warm-up, then one timed run). A
/// tabletop run stops once its stepping has taken `budgetSeconds` of wall
/// time: its cost is then that of the part it ran, its window unmeasured,
/// and the larger sizes are left out (a pile costs more with every body).
std::vector<PilePoint> measurePiles(const std::vector<int>& sizes, double budgetSeconds, int threads,
                                    const MeasureHooks& hooks);

/// The growth exponent of tabletop's and Bullet's cost over the piles
/// ("tabletop", "bullet").
std::map<std::string, double> pileExponents(const std::vector<PilePoint>& points);

}  // namespace tabletop
