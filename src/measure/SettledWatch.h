#pragma once

#include <vector>

class btRigidBody;

namespace tabletop {

/// What a scene does once it should be at rest, over a window of time.
/// SI units.
struct Settled {
  bool measured = false;     ///< false if the run ended before the window did
  double drift = 0.0;        ///< m: the farthest any body's centre moved over the window
  double penetration = 0.0;  ///< m: the deepest contact at the end of any step in it
  double energyGain = 0.0;   ///< J: the largest rise of the mechanical energy over its lowest in it
};

/// Kinetic (translational and rotational) plus potential energy above the
/// floor of a body, J; 0 for a static one.
double mechanicalEnergy(const btRigidBody& body, double gravity);

/// Watches a window [from, to] s step by step, the same way for tabletop's
/// world and for Bullet's own, so the two are judged alike.
class SettledWatch {
 public:
  SettledWatch(double from, double to, double gravity) : from_(from), to_(to), gravity_(gravity) {}
  /// After a step ending at `time` s: the bodies and the deepest contact, m.
  void observe(double time, const std::vector<const btRigidBody*>& bodies, double deepest);
  const Settled& result() const { return result_; }

 private:
  double from_, to_, gravity_;
  bool started_ = false;
  double lowest_ = 0.0;
  std::vector<double> start_;  // x, y, z of each centre at the window's start
  Settled result_;
};

}  // namespace tabletop
