#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <sys/types.h>

namespace tabletop {

/// The most threads a WorkerThreads (and so --threads, TABLETOP_THREADS)
/// may use.
inline constexpr int kMaxThreads = 256;

/// The cores this machine offers the process (at least 1, at most
/// kMaxThreads).
int availableThreads();

/// A thread count written as text (--threads, TABLETOP_THREADS, Python's
/// `threads`): a whole number from 1 to kMaxThreads, else nothing.
std::optional<int> threadCount(const std::string& text);

/// A fixed set of threads that share out a list of items: forEach() hands
/// each item to whichever thread is free, the calling thread one of them,
/// and returns once all are done. Which thread takes which item varies
/// from run to run, so a job must give the same result whichever worker
/// runs it (each worker index its own scratch). The threads start at the
/// first call that has work for more than one, and sleep between calls.
/// A process forked from the one that started them has none of them: in
/// it every call runs on the calling thread alone.
class WorkerThreads {
 public:
  /// `threads` in all, the calling thread included (clamped to
  /// [1, kMaxThreads]).
  explicit WorkerThreads(int threads);
  ~WorkerThreads();
  WorkerThreads(const WorkerThreads&) = delete;
  WorkerThreads& operator=(const WorkerThreads&) = delete;

  int size() const { return size_; }
  /// What a worker does with an item: job(item, worker), worker in
  /// [0, size()), 0 the calling thread.
  using Job = std::function<void(std::size_t item, int worker)>;
  /// Runs job on every item in [0, count). The first exception a job
  /// throws is thrown here once every worker has stopped; the items not
  /// yet begun are then left undone.
  void forEach(std::size_t count, const Job& job);

 private:
  void start();
  void serve(int worker);
  void work(int worker);
  int size_;
  pid_t owner_ = 0;  // the process that started the threads (0: none started)
  // Held by pointer: a forked child leaks it rather than join threads it
  // does not have.
  std::unique_ptr<std::vector<std::thread>> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const Job* job_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> next_{0};
  long round_ = 0;  // forEach calls that woke the threads
  int busy_ = 0;    // threads still working on this round
  bool stop_ = false;
  std::exception_ptr error_;
};

}  // namespace tabletop
