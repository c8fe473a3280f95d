// tabletop.sweep(spec, client=None): a sweep's table as a pandas DataFrame,
// its runs here or, given a dask.distributed client, on the cluster's
// workers. The workers are sent the spec whole, its scene inlined
// (SweepSpec::selfContained), so they need the module but none of the files.
#include "python/SweepBinding.h"

#include <algorithm>
#include <string>
#include <vector>

#include <pybind11/eval.h>
#include <pybind11/stl.h>

#include "python/Arguments.h"
#include "scenario/ScenarioError.h"
#include "sweep/SweepPool.h"

namespace py = pybind11;

namespace tabletop {
namespace {

using python::shippedScenes;

// The most runs one cluster task holds.
constexpr std::size_t kRunsPerTask = 32;

// A spec given as a path, a JSON text or a dict.
SweepSpec specFrom(const py::object& spec) {
  if (py::isinstance<py::dict>(spec)) {
    const std::string text = py::module_::import("json").attr("dumps")(spec).cast<std::string>();
    return loadSweepText(text, "<spec>", shippedScenes());
  }
  const std::string s = py::str(spec).cast<std::string>();
  if (!s.empty() && s.front() == '{') return loadSweepText(s, "<spec>", shippedScenes());
  return loadSweepFile(s, shippedScenes());
}

py::object fromJson(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

// Runs of a self-contained spec: their rows as lists. What the workers
// run, a few runs a task, so a task's cost (sending it, loading the spec)
// is shared. The spec was checked where it was made: its runs are not
// checked again here.
py::object sweepRows(const std::string& selfContained, const std::vector<std::size_t>& indices) {
  const SweepSpec spec = loadSweepText(selfContained, "<spec>", shippedScenes(), false);
  for (std::size_t i : indices) {
    if (i >= spec.runs()) throw py::index_error("the sweep has " + std::to_string(spec.runs()) + " runs");
  }
  std::vector<SweepRow> rows;
  {
    py::gil_scoped_release release;
    for (std::size_t i : indices) rows.push_back(runSweepRow(spec, i));
  }
  return fromJson(rows);
}

// The task sent to the workers: a Python function that imports the module
// where it runs. The module's own functions cannot be pickled (they hold
// a C pointer); a function defined here, outside any importable module,
// travels by value.
py::object workerTask() {
  py::dict scope;
  scope["__name__"] = "tabletop_sweep_task";
  py::exec(R"(
def run(spec, indices):
    import tabletop
    return tabletop._sweep_rows(spec, indices)
)",
           scope);
  return scope["run"];
}

py::object sweep(const py::object& specObject, const py::object& client, int jobs) {
  const SweepSpec spec = specFrom(specObject);
  const std::vector<std::string> columns = sweepColumns(spec);
  py::list rows;
  if (client.is_none()) {
    std::vector<SweepRow> done;
    bool interrupted = false;
    {
      py::gil_scoped_release release;
      runSweepPool(
          spec, 0, spec.runs(), jobs, [&done](const SweepRow& r) { done.push_back(r); },
          [&interrupted] {
            py::gil_scoped_acquire gil;
            interrupted = interrupted || PyErr_CheckSignals() != 0;
            return interrupted;
          });
    }
    if (interrupted) throw py::error_already_set();
    for (const SweepRow& r : done) rows.append(fromJson(r));
  } else {
    // A task per few runs, four tasks or more per worker thread, so the
    // cluster's threads stay busy to the end.
    const std::string text = spec.selfContained();
    std::size_t threads = 0;
    for (const auto& item : client.attr("nthreads")().cast<py::dict>()) threads += item.second.cast<std::size_t>();
    const std::size_t chunk =
        std::clamp<std::size_t>(spec.runs() / (4 * std::max<std::size_t>(threads, 1)), 1, kRunsPerTask);
    py::list chunks, texts;
    for (std::size_t i = 0; i < spec.runs(); i += chunk) {
      py::list indices;
      for (std::size_t k = i; k < std::min(spec.runs(), i + chunk); ++k) indices.append(k);
      chunks.append(indices);
      texts.append(text);
    }
    for (const py::handle part : client.attr("gather")(client.attr("map")(workerTask(), texts, chunks))) {
      for (const py::handle row : part) rows.append(row);
    }
  }
  return py::module_::import("pandas").attr("DataFrame")(rows, py::arg("columns") = columns);
}

}  // namespace

void addSweep(py::module_& m) {
  m.def("sweep", &sweep, py::arg("spec"), py::arg("client") = py::none(), py::kw_only(), py::arg("jobs") = 1,
        "Runs a sweep (docs/sweep.md): `spec` is a spec file's path, its JSON text or a dict. Returns the table "
        "`tabletop sweep` writes as a pandas DataFrame, one row per run in run order. Given a dask.distributed "
        "Client, the runs go to its workers (which need the module installed); else they run here, on `jobs` "
        "forked worker processes. The rows are the same either way, state_hash for state_hash.");
  m.def("_sweep_rows", &sweepRows, py::arg("spec"), py::arg("indices"),
        "Runs of a self-contained sweep spec, each a list in the table's columns: what tabletop.sweep's "
        "cluster workers and tabletop sweep --scheduler's run.");
}

}  // namespace tabletop
