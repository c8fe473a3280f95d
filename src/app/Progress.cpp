#include "app/Progress.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include <unistd.h>

namespace tabletop {
namespace {

constexpr int kWidth = 30;          // characters of bar
constexpr double kRedraw = 0.1;     // seconds between redraws, at most ten a second

std::string duration(double seconds) {
  const long s = std::lround(seconds);
  if (s < 60) return std::to_string(s) + " s";
  return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
}

}  // namespace

Progress::Progress(std::ostream& err)
    : err_(err), shown_(isatty(STDERR_FILENO)), started_(std::chrono::steady_clock::now()), drawn_(started_) {}

Progress::~Progress() {
  if (shown_ && drawnAny_) err_ << "\r\033[K" << std::flush;
}

void Progress::start(long total) { total_ = std::max(total, done_); }

void Progress::set(long done, const std::string& what) {
  done_ = done;
  total_ = std::max(total_, done_);
  if (!shown_) return;
  const auto now = std::chrono::steady_clock::now();
  const double spent = std::chrono::duration<double>(now - started_).count();
  if (spent < kFirstDraw || std::chrono::duration<double>(now - drawn_).count() < kRedraw) return;
  drawn_ = now;
  drawnAny_ = true;
  const int filled = static_cast<int>(kWidth * done_ / std::max(1L, total_));
  err_ << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, ' ') << "] " << done_ << "/" << total_;
  if (done_ > 0 && done_ < total_) err_ << ", " << duration(spent / done_ * (total_ - done_)) << " left";
  err_ << " " << what << "\033[K" << std::flush;
}

}  // namespace tabletop
