#pragma once

#include <string>
#include <vector>

namespace tabletop {

/// The command that bridges a sweep to a Dask cluster for runSweepBridge:
/// python3 running a short script that connects a dask.distributed client
/// to `scheduler` ("tcp://HOST:8786"), submits each run it is sent as a
/// task calling the `tabletop` module on the workers, and writes each row
/// back as it finishes. The Python is TABLETOP_PYTHON if set, else python3
/// on the PATH; it must find the module and dask.distributed.
std::vector<std::string> daskBridgeCommand(const std::string& scheduler);

/// "" when `scheduler` reads as a Dask address (tcp://, tls:// or
/// inproc:// and a printable host of at most 256 bytes), else why not.
std::string schedulerProblem(const std::string& scheduler);

}  // namespace tabletop
