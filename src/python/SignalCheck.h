#pragma once

#include <chrono>

namespace tabletop::python {

/// Thrown when Python's error indicator is set (KeyboardInterrupt, or what
/// a signal handler raised) and the call must end; the module's exception
/// translator leaves that error as the call's outcome.
struct PythonErrorSet {};

/// Lets a long call, run with the GIL released, be stopped by Ctrl-C: at
/// most every kInterval of wall time it takes the GIL and runs Python's
/// signal handlers (PyErr_CheckSignals), and throws PythonErrorSet when
/// one raised. Called once per step: between those looks it costs a read
/// of the clock. Only the main thread runs handlers, as in Python itself.
class SignalCheck {
 public:
  static constexpr std::chrono::milliseconds kInterval{50};

  void operator()();

 private:
  std::chrono::steady_clock::time_point next_ = std::chrono::steady_clock::now() + kInterval;
};

}  // namespace tabletop::python
