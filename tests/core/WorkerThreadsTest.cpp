// WorkerThreads: every item is done once, by some worker in range, the
// calling thread among them; a job's exception comes back to the caller;
// a process forked from one whose threads run does the work alone.

#include "core/WorkerThreads.h"

#include <atomic>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

namespace tabletop {
namespace {

TEST(WorkerThreads, DoesEveryItemOnceOnItsWorkers) {
  for (const int size : {1, 2, 4, 9}) {
    WorkerThreads threads(size);
    ASSERT_EQ(threads.size(), size);
    for (const std::size_t count : {0u, 1u, 3u, 100u, 1000u}) {
      std::vector<std::atomic<int>> done(count);
      std::atomic<int> outOfRange{0};
      threads.forEach(count, [&](std::size_t item, int worker) {
        if (worker < 0 || worker >= size) ++outOfRange;
        ++done[item];
      });
      EXPECT_EQ(outOfRange.load(), 0);
      for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(done[i].load(), 1) << size << " threads, item " << i;
    }
  }
}

TEST(WorkerThreads, SizeIsClamped) {
  EXPECT_EQ(WorkerThreads(0).size(), 1);
  EXPECT_EQ(WorkerThreads(-3).size(), 1);
  EXPECT_EQ(WorkerThreads(kMaxThreads + 1).size(), kMaxThreads);
  EXPECT_GE(availableThreads(), 1);
  EXPECT_LE(availableThreads(), kMaxThreads);
}

TEST(WorkerThreads, AJobsExceptionReachesTheCaller) {
  WorkerThreads threads(3);
  EXPECT_THROW(threads.forEach(200,
                               [](std::size_t item, int) {
                                 if (item == 17) throw std::runtime_error("item 17");
                               }),
               std::runtime_error);
  // The threads still serve the next call.
  std::atomic<int> done{0};
  threads.forEach(50, [&](std::size_t, int) { ++done; });
  EXPECT_EQ(done.load(), 50);
}

TEST(WorkerThreads, AForkedChildWorksAlone) {
  WorkerThreads threads(3);
  threads.forEach(10, [](std::size_t, int) {});  // the threads are running
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    int sum = 0;
    bool onlyCaller = true;
    threads.forEach(10, [&](std::size_t item, int worker) {
      sum += static_cast<int>(item);
      onlyCaller = onlyCaller && worker == 0;
    });
    ::_exit(sum == 45 && onlyCaller ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace tabletop
