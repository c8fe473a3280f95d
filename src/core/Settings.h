#pragma once

#include "core/Broadphase.h"
#include "core/ContactSolver.h"
#include "core/Gyroscopic.h"
#include "core/Integrator.h"

namespace tabletop {

/// The timesteps and run lengths every mode accepts: a step from 10 us to
/// 0.1 s, and at most kMaxSteps steps in one run (about 12 hours of wall
/// time at the slowest settings, so a typo cannot start a run that never
/// ends).
inline constexpr double kMinTimestep = 1e-5;
inline constexpr double kMaxTimestep = 0.1;
inline constexpr double kMaxSteps = 1e7;

/// The knobs of full physics alone (Bullet's solver and collision world);
/// the rules ignore them. Read flat from a scenario's "settings" (their
/// keys are listed in scenarios/README.md).
struct BulletSettings {
  bool sleeping = false;  ///< let Bullet deactivate bodies at rest
  /// The share of each contact's impulse from the step before that the
  /// solver starts from (Bullet's warm starting factor; its own default is
  /// 0.85). 1 carries a resting stack's load from step to step whole.
  double warmStart = 1.0;
  /// Stop the solver's iterations early once one sweep changes the
  /// velocities by less than this, m/s (root of the summed squares over
  /// all rows); 0 runs every iteration. With it, `iterations` is a cap.
  double solverTolerance = 0.0;
  /// How a spinning body's gyroscopic term enters (Bullet's default, the
  /// implicit step in body axes; docs/hard-cases.md, compares them).
  Gyroscopic gyroscopic = Gyroscopic::ImplicitBody;

  // What the collision world models (docs/bench.md, "Modelling only what a
  // scene needs", has what each saves and costs).
  Broadphase broadphase = Broadphase::Dbvt;  ///< how overlapping pairs are found
  /// The table's legs join the collision world only once a body can reach
  /// them (its bounding box comes down to the underside of the top).
  bool legsWhenReachable = true;
  /// The floor pairs only with bodies whose bounding box comes down to it
  /// (a half-space's bound), not with every body (an infinite plane's).
  bool floorPairsNearFloor = true;
};

/// How a scene is stepped: one value, resolved once per run (scenario,
/// then the command line), that every mode reads. Defaults are documented
/// in scenarios/README.md.
struct Settings {
  double timestep = 1.0 / 240.0;  ///< fixed step, seconds
  int iterations = 10;            ///< constraint solver iterations per step
  /// How contact impulses are found: by `iterations` sweeps, every island
  /// solved exactly, or each island its own way (docs/hard-cases.md).
  ContactSolver solver = ContactSolver::Automatic;
  /// Full physics cuts a step into up to this many equal parts while a
  /// body moves fast for its size (docs/hard-cases.md); 1 never does.
  int maxSubsteps = 64;
  double duration = 10.0;         ///< longest simulated time, seconds
  double gravity = 9.81;          ///< m/s^2, acting along -Y
  bool endAtRest = true;          ///< stop once the script is done and all is at rest
  Integrator integrator = Integrator::Trapezoid;  ///< how positions follow velocities
  BulletSettings bullet;          ///< full physics only
  /// Threads full physics solves independent islands on (1: the calling
  /// thread alone). Not a scene's: the command line's --threads or
  /// TABLETOP_THREADS, or Python's `threads`, sets it; any count gives the
  /// same states to the bit (docs/step.md, "Threads").
  int threads = 1;
};

}  // namespace tabletop
