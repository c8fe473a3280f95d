#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

namespace tabletop {

/// A bar on standard error, redrawn in place with what is done and an
/// estimate of the time left, when standard error is a terminal and the
/// work has taken kFirstDraw seconds; silent otherwise (a log or a pipe gets
/// no control characters, a quick command no flicker). Cleared when it goes.
class Progress {
 public:
  static constexpr double kFirstDraw = 0.5;  // seconds
  explicit Progress(std::ostream& err);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress();

  /// How many steps the work has; may be set again as the estimate changes.
  void start(long total);
  /// One step done; `what` names it.
  void advance(const std::string& what) { set(done_ + 1, what); }
  /// `done` steps done; `what` names the work.
  void set(long done, const std::string& what);

 private:
  std::ostream& err_;
  bool shown_;
  long total_ = 0;
  long done_ = 0;
  bool drawnAny_ = false;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point drawn_;
};

}  // namespace tabletop
