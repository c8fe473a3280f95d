#include "python/SignalCheck.h"

#include <pybind11/pybind11.h>

namespace tabletop::python {

void SignalCheck::operator()() {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return;
  next_ = now + kInterval;
  const pybind11::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw PythonErrorSet{};
}

}  // namespace tabletop::python
