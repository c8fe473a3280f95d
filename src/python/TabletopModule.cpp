// `import tabletop`: scenarios loaded from files or built from Python
// objects, run whole (the run `tabletop run --json` prints) or stepped
// from Python in any of the three modes, their state as NumPy arrays, and
// frames rendered headless into NumPy images. Errors are Python
// exceptions carrying the command line's located messages; docs/library.md
// says what the module guarantees (checked arguments, bounded calls,
// threads). Each part binds itself (Bindings.h); this file puts them
// together.
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "python/Bindings.h"
#include "python/SweepBinding.h"

PYBIND11_MODULE(tabletop, m) {
  namespace py = pybind11;
  m.doc() =
      "tabletop: the table-top scenes of S. Zou's report \"The Design of a 3D-Object Simulator Using Open-GL\" "
      "(Concordia, 2001) simulated with Bullet rigid-body physics, in three modes: bullet (full physics), compat "
      "(Bullet held to the report's rules) and rules (the report's rules alone). SI units, Y up, angles in degrees.";
  m.attr("__version__") = TABLETOP_VERSION;

  // NumPy first, so that its absence says what to install.
  try {
    py::module_::import("numpy");
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ImportError)) throw;
    // A C++ exception becomes the import's own ImportError, with this text
    // (PYBIND11_MODULE wraps a Python one in "initialization failed").
    throw py::import_error(std::string("tabletop needs NumPy, which could not be imported (") + e.what() +
                           "): install it with `apt-get install python3-numpy` (Debian, Ubuntu) or "
                           "`pip install numpy`");
  }
  // NumPy's C API is looked up now, once, while the import holds the GIL.
  // pybind11 looks it up on first use inside a function-local static, so
  // importing NumPy under the static's guard: two threads making their
  // first array at once deadlocked, one holding the guard and waiting for
  // the GIL, the other holding the GIL and waiting for the guard.
  py::array_t<std::uint8_t>(0);

  tabletop::python::bindScenarios(m);
  tabletop::python::bindSimulation(m);
  tabletop::python::bindImages(m);
  tabletop::addSweep(m);
}
