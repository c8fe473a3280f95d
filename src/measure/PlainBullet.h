#pragma once

#include <vector>

#include "core/Vec3.h"
#include "measure/SettledWatch.h"
#include "scenario/Scenario.h"

namespace tabletop {

/// A scene in Bullet's own default pipeline, what a Bullet user would
/// write: btDefaultCollisionConfiguration, btCollisionDispatcher,
/// btDbvtBroadphase and btSequentialImpulseConstraintSolver at Bullet's
/// defaults (10 iterations, warm starting 0.85, Euler positions); the
/// table top a static box and its legs static cylinders, the floor a
/// static plane; each entity a body of the same shape, mass, material,
/// pose and velocity as tabletop starts it; each push of the script
/// applied as the same impulse at its own time (a push with no time, at
/// the start). No sleeping, as in tabletop. The yardstick of tabletop's
/// cost (bench --baseline).
struct PlainRun {
  double costMsPerSecond = 0;  ///< median wall time per simulated second, ms
  double simulated = 0;        ///< s
  std::vector<Vec3> centres;   ///< every entity's final centre, m
  /// m: the farthest any entity's centre got from its start, watched
  /// after every step of the untimed warm-up run.
  double worstDrift = 0;
  Settled settled;  ///< the window asked for, watched in the warm-up run
};

/// Runs `scenario` for `duration` s at `timestep`, `repeats` times after a
/// warm-up; the warm-up watches the settled window [settledFrom,
/// duration] s when settledFrom >= 0.
PlainRun runPlainBullet(const Scenario& scenario, double timestep, double duration, int repeats,
                        double settledFrom = -1.0);

}  // namespace tabletop
