#include "core/WorkerThreads.h"

#include <algorithm>
#include <utility>

#include <unistd.h>

namespace tabletop {

int availableThreads() {
  const long n = ::sysconf(_SC_NPROCESSORS_ONLN);
  return static_cast<int>(std::clamp<long>(n, 1, kMaxThreads));
}

std::optional<int> threadCount(const std::string& text) {
  if (text.empty() || text.size() > 3) return std::nullopt;
  int n = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    n = 10 * n + (c - '0');
  }
  if (n < 1 || n > kMaxThreads) return std::nullopt;
  return n;
}

WorkerThreads::WorkerThreads(int threads) : size_(std::clamp(threads, 1, kMaxThreads)) {}

WorkerThreads::~WorkerThreads() {
  if (!threads_) return;
  if (owner_ != ::getpid()) {
    (void)threads_.release();  // a forked child: the threads are its parent's
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : *threads_) t.join();
}

void WorkerThreads::start() {
  owner_ = ::getpid();
  threads_ = std::make_unique<std::vector<std::thread>>();
  threads_->reserve(static_cast<std::size_t>(size_ - 1));
  for (int w = 1; w < size_; ++w) threads_->emplace_back([this, w] { serve(w); });
}

void WorkerThreads::forEach(std::size_t count, const Job& job) {
  if (count == 0) return;
  if (size_ == 1 || count == 1 || (threads_ && owner_ != ::getpid())) {
    for (std::size_t i = 0; i < count; ++i) job(i, 0);
    return;
  }
  if (!threads_) start();
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    job_ = &job;
    count_ = count;
    next_.store(0);
    error_ = nullptr;
    busy_ = size_ - 1;
    ++round_;
  }
  wake_.notify_all();
  work(0);
  std::unique_lock<std::mutex> lock(mutex_);
  done_.wait(lock, [this] { return busy_ == 0; });
  job_ = nullptr;
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void WorkerThreads::serve(int worker) {
  long seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || round_ != seen; });
      if (stop_) return;
      seen = round_;
    }
    work(worker);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      --busy_;
    }
    done_.notify_one();
  }
}

void WorkerThreads::work(int worker) {
  for (std::size_t i = next_.fetch_add(1); i < count_; i = next_.fetch_add(1)) {
    try {
      (*job_)(i, worker);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
      next_.store(count_);
    }
  }
}

}  // namespace tabletop
