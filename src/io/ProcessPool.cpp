#include "io/ProcessPool.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace tabletop {
namespace {

using nlohmann::json;

// One worker process and the two pipes to it: job indices go down, rows
// (JSON arrays, one per line) come back.
struct Worker {
  pid_t pid = -1;
  int tasks = -1;
  int results = -1;
  std::string buffer;      // what came back that is not yet a whole line
  std::size_t given = 0;   // jobs sent and not yet back
  long last = -1;          // the last job sent
};

bool writeAll(int fd, const std::string& text) {
  for (std::size_t at = 0; at < text.size();) {
    const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += static_cast<std::size_t>(n);
  }
  return true;
}

// The worker's whole life: reads job indices, one per line, and writes
// back each job's row; ends when its task pipe closes. Ctrl-C is the
// parent's to handle: the parent ends its workers.
[[noreturn]] void workerMain(const PoolJob& job, int tasks, int results) {
  std::signal(SIGINT, SIG_IGN);
  std::signal(SIGTERM, SIG_DFL);
  std::string pending;
  char chunk[256];
  for (;;) {
    const ssize_t n = ::read(tasks, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(0);
    pending.append(chunk, static_cast<std::size_t>(n));
    for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos;) {
      const std::size_t index = std::stoul(pending.substr(0, nl));
      pending.erase(0, nl + 1);
      std::string line;
      try {
        line = json(job(index)).dump(-1, ' ', false, json::error_handler_t::replace);
      } catch (const std::exception& e) {
        line = json{{"error", e.what()}}.dump(-1, ' ', false, json::error_handler_t::replace);
      }
      if (!writeAll(results, line + "\n")) ::_exit(1);
    }
  }
}

// Starts a worker: this process forked, or with `program` that program
// (its standard input the task pipe, its output the rows). The child
// closes the pipes of the workers before it, so each worker's task pipe
// has one writer and closing it ends the worker.
Worker startWorker(const PoolJob& job, const std::vector<Worker>& others,
                   const std::vector<std::string>& program = {}) {
  int down[2], up[2];
  if (::pipe2(down, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  if (::pipe2(up, O_CLOEXEC) != 0) {
    ::close(down[0]);
    ::close(down[1]);
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    for (int fd : {down[0], down[1], up[0], up[1]}) ::close(fd);
    throw std::runtime_error(std::string("cannot start a worker process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    for (const Worker& w : others) {
      ::close(w.tasks);
      ::close(w.results);
    }
    ::close(down[1]);
    ::close(up[0]);
    if (program.empty()) workerMain(job, down[0], up[1]);
    // The program's standard input and output are the pipes (dup2 clears
    // close-on-exec); its errors go where ours do.
    if (::dup2(down[0], 0) < 0 || ::dup2(up[1], 1) < 0) ::_exit(127);
    std::vector<char*> argv;
    for (const std::string& a : program) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(down[0]);
  ::close(up[1]);
  Worker w;
  w.pid = pid;
  w.tasks = down[1];
  w.results = up[0];
  return w;
}

// Ends the workers: their task pipes closed, and killed unless `finished`.
struct Workers {
  std::vector<Worker> list;
  std::string what = "the worker process";  // as messages name one
  bool finished = false;
  struct sigaction previousPipe {};
  Workers() {
    // A worker that died is seen as the end of its pipe, not as SIGPIPE.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGPIPE, &ignore, &previousPipe);
  }
  ~Workers() {
    for (Worker& w : list) {
      ::close(w.tasks);
      ::close(w.results);
      if (w.pid <= 0) continue;  // reaped already
      if (!finished) ::kill(w.pid, SIGKILL);
      while (::waitpid(w.pid, nullptr, 0) < 0 && errno == EINTR) {
      }
    }
    ::sigaction(SIGPIPE, &previousPipe, nullptr);
  }
};

// Hands jobs [first, first + count) to the workers, at most `depth` to
// each at once, and the rows back to `onRow` in job order.
void drive(Workers& workers, std::size_t depth, std::size_t first, std::size_t count,
           const std::function<void(const PoolRow&)>& onRow, const std::function<bool()>& stop) {
  const std::size_t end = first + count;
  std::size_t next = first, nextOut = first;
  const auto give = [&next, end, depth](Worker& w) {
    std::string lines;
    for (; next < end && w.given < depth; ++next, ++w.given) {
      lines += std::to_string(next) + "\n";
      w.last = static_cast<long>(next);
    }
    if (!writeAll(w.tasks, lines)) throw std::runtime_error("a worker process stopped reading");
  };
  for (Worker& w : workers.list) give(w);
  std::map<std::size_t, PoolRow> waiting;  // finished out of order, at most depth x workers of them
  while (nextOut < end && !stop()) {
    std::vector<pollfd> fds;
    for (const Worker& w : workers.list) fds.push_back({w.results, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), 100) < 0 && errno != EINTR) {
      throw std::runtime_error(std::string("cannot wait for the workers: ") + std::strerror(errno));
    }
    for (std::size_t k = 0; k < fds.size(); ++k) {
      if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      Worker& w = workers.list[k];
      char chunk[1 << 16];
      const ssize_t n = ::read(w.results, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        int status = 0;
        ::waitpid(w.pid, &status, 0);
        w.pid = -1;
        throw std::runtime_error(workers.what + " ended before run " + std::to_string(w.last) + "'s row," +
                                 (WIFSIGNALED(status) ? std::string(" killed by ") + strsignal(WTERMSIG(status))
                                                      : " status " + std::to_string(WEXITSTATUS(status))));
      }
      w.buffer.append(chunk, static_cast<std::size_t>(n));
      for (std::size_t nl; (nl = w.buffer.find('\n')) != std::string::npos;) {
        const json row = json::parse(w.buffer.substr(0, nl), nullptr, false);
        w.buffer.erase(0, nl + 1);
        if (!row.is_array() || row.empty() || !row[0].is_number_unsigned()) {
          throw std::runtime_error("a worker: " + (row.is_object() ? row.value("error", "") : "not a row"));
        }
        waiting[row[0].get<std::size_t>()] = PoolRow(row.begin(), row.end());
        --w.given;
        give(w);
      }
    }
    // The rows in run order, as far as they go.
    for (auto it = waiting.find(nextOut); it != waiting.end() && !stop(); it = waiting.find(nextOut)) {
      onRow(it->second);
      waiting.erase(it);
      ++nextOut;
    }
  }
  workers.finished = nextOut == end;
}

}  // namespace

void runProcessPool(std::size_t first, std::size_t count, int jobs, const PoolJob& job,
                    const std::function<void(const PoolRow&)>& onRow, const std::function<bool()>& stop) {
  if (count == 0) return;
  jobs = static_cast<int>(std::min<std::size_t>(std::clamp(jobs, 1, kMaxJobs), count));
  Workers workers;
  for (int k = 0; k < jobs; ++k) workers.list.push_back(startWorker(job, workers.list));
  drive(workers, 1, first, count, onRow, stop);
}

void runBridgePool(const std::string& firstLine, std::size_t first, std::size_t count,
                   const std::vector<std::string>& program, const std::function<void(const PoolRow&)>& onRow,
                   const std::function<bool()>& stop) {
  if (count == 0) return;
  Workers workers;
  workers.what = program.front();
  workers.list.push_back(startWorker({}, {}, program));
  if (!writeAll(workers.list.front().tasks, firstLine + "\n")) {
    throw std::runtime_error("the program " + program.front() + " did not start");
  }
  drive(workers, kMaxBridgeRuns, first, count, onRow, stop);
}

}  // namespace tabletop
