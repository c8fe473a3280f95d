#pragma once

#include <csignal>

namespace tabletop {

/// While one is alive, SIGINT (Ctrl-C) and SIGTERM only raise a flag, which
/// long commands (render, bench) check between units of work: they stop
/// cleanly, keeping every output already complete and leaving none half
/// written. A second signal acts at once, as without the guard (each
/// handler resets itself).
///
/// A signal handler cannot be handed any state, so the flag is the one
/// piece of static state in tabletop, private to InterruptGuard.cpp.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// True once SIGINT or SIGTERM arrived.
  bool requested() const;
  /// The signal that arrived, or 0.
  int signal() const;

  /// Thrown by throwIfRequested(), to leave a run from inside its step
  /// observer; the command catches it and exits with status 130.
  struct Interrupted {};
  void throwIfRequested() const {
    if (requested()) throw Interrupted{};
  }

 private:
  struct sigaction previousInt_ {};
  struct sigaction previousTerm_ {};
};

}  // namespace tabletop
