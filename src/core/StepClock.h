#pragma once

namespace tabletop {

/// Simulated time at a fixed timestep that may change between steps: the
/// time of step n is t0 + (n - n0) dt, where (n0, t0) is the last change,
/// so while a rate holds each time is an exact multiple as from the start.
class StepClock {
 public:
  /// The time after `steps` steps of `timestep` s since the last change.
  double time(long steps, double timestep) const { return t0_ + static_cast<double>(steps - n0_) * timestep; }
  /// A new timestep from step `steps`, reached at `now` s.
  void changeAt(long steps, double now) {
    n0_ = steps;
    t0_ = now;
  }

 private:
  long n0_ = 0;
  double t0_ = 0.0;
};

}  // namespace tabletop
