#include "sweep/DaskBridge.h"

#include <cstdlib>

#include "core/Text.h"

namespace tabletop {
namespace {

// The bridge. A thread reads the run numbers and submits a task for each;
// the main thread writes rows as their tasks finish. A task's function is
// defined here, in __main__, so it travels to the workers by value; it
// imports the module where it runs. The process ends when its input ends
// and every task sent is back; killed, its client's tasks are cancelled.
constexpr const char* kScript = R"(
import json, os, queue, sys, threading
from distributed import Client

def run(spec, indices):
    import tabletop
    return tabletop._sweep_rows(spec, indices)

try:
    client = Client(sys.argv[1], timeout="30s")
except Exception as e:
    sys.exit("tabletop sweep: --scheduler %s: cannot connect: %s" % (sys.argv[1], e))
done = queue.Queue()

def submit():
    # The spec's line, then run numbers: those that came in one read go
    # out as tasks of at most 32 runs.
    pending, spec, count = b"", None, 0
    while True:
        data = os.read(0, 1 << 16)
        if not data:
            break
        pending += data
        *lines, pending = pending.split(b"\n")
        if spec is None and lines:
            spec = lines.pop(0).decode()
        runs = [int(line) for line in lines]
        for k in range(0, len(runs), 32):
            future = client.submit(run, spec, runs[k:k + 32], pure=False)
            future.add_done_callback(done.put)
            count += 1
    done.put(count)

threading.Thread(target=submit, daemon=True).start()
sent, back = None, 0
while sent is None or back < sent:
    item = done.get()
    if isinstance(item, int):
        sent = item
        continue
    back += 1
    try:
        rows = item.result()
    except Exception as e:
        rows = [{"error": "%s: %s" % (type(e).__name__, e)}]
    sys.stdout.write("".join(json.dumps(row) + "\n" for row in rows))
    sys.stdout.flush()
client.close()
)";

}  // namespace

std::vector<std::string> daskBridgeCommand(const std::string& scheduler) {
  const char* python = std::getenv("TABLETOP_PYTHON");
  return {python && *python ? python : "python3", "-c", kScript, scheduler};
}

std::string schedulerProblem(const std::string& scheduler) {
  bool known = false;
  for (const char* scheme : {"tcp://", "tls://", "inproc://"}) known = known || scheduler.rfind(scheme, 0) == 0;
  if (!known || scheduler.size() > 256 || unprintableProblem(scheduler) || scheduler.find(' ') != std::string::npos) {
    return "expected a Dask scheduler's address (tcp://HOST:8786), got \"" + shownText(scheduler, 64) + "\"";
  }
  return "";
}

}  // namespace tabletop
