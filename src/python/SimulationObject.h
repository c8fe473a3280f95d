#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

#include <pybind11/pybind11.h>

#include "python/SteppedScene.h"

namespace tabletop::python {

/// What a Python `Simulation` holds: its scene, or none once closed, and
/// the lock that lets one call at a time use it. A call waits for another
/// thread's call on the same object to end, with the GIL released so that
/// call can finish (the lock is only ever waited for without the GIL,
/// which rules out a deadlock between the two). A call made from inside
/// another in the same thread (a signal handler run during a step) is
/// refused rather than left waiting for itself.
class SimulationObject {
 public:
  /// `origin` is how the scene was made, for copies and pickles: the
  /// scenario's text and file name, the mode, whether the script runs, and
  /// the settings given to the constructor.
  SimulationObject(std::unique_ptr<SteppedScene> scene, pybind11::tuple origin)
      : scene_(std::move(scene)), origin_(std::move(origin)) {}

  /// The scene for the length of one call, locked.
  class Use {
   public:
    explicit Use(SimulationObject& object);
    ~Use();
    Use(const Use&) = delete;
    Use& operator=(const Use&) = delete;
    SteppedScene& operator*() const { return *object_.scene_; }
    SteppedScene* operator->() const { return object_.scene_.get(); }

   private:
    SimulationObject& object_;
    std::unique_lock<std::mutex> lock_;
  };

  /// Locks the scene for one call: a RuntimeError when closed.
  Use use() { return Use(*this); }
  /// Frees the scene; every later call but close() raises RuntimeError.
  void close();
  bool closed();
  const pybind11::tuple& origin() const { return origin_; }

 private:
  /// Waits for the lock with the GIL released; refuses a call from the
  /// thread that holds it.
  std::unique_lock<std::mutex> lock();

  std::mutex mutex_;
  std::atomic<std::thread::id> owner_{};
  std::unique_ptr<SteppedScene> scene_;
  pybind11::tuple origin_;
};

/// Where `self` (a Simulation, else a TypeError) keeps its object: the
/// pybind11 internals the module's __init__ fills in.
pybind11::detail::value_and_holder valueAndHolder(const pybind11::handle& self);
/// The object of `self`, or a RuntimeError when there is none: one made by
/// Simulation.__new__ whose __init__ never ran. (Taking `self` as a
/// SimulationObject* would not do: pybind11 hands such an object a pointer
/// to fresh, unconstructed memory.)
SimulationObject& initialised(const pybind11::handle& self);

/// `f(scene)` for one call on `self`, the scene locked for it.
template <class F>
auto with(const pybind11::handle& self, F&& f) {
  const SimulationObject::Use use = initialised(self).use();
  return f(*use);
}

}  // namespace tabletop::python
