#pragma once

namespace tabletop {

/// How a scene is stepped. Every mode reads the same settings; defaults are
/// documented in scenarios/README.md.
struct Settings {
  double timestep = 1.0 / 240.0;  ///< fixed step, seconds
  int iterations = 10;            ///< constraint solver iterations per step
  double duration = 10.0;         ///< longest simulated time, seconds
  double gravity = 9.81;          ///< m/s^2, acting along -Y
  bool endAtRest = true;          ///< stop once the script is done and all is at rest
  bool sleeping = false;          ///< let Bullet deactivate bodies at rest
};

}  // namespace tabletop
