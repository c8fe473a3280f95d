// tabletop.write_png: a frame from render() (or any H x W x 3 uint8 array)
// saved as a PNG without a package Debian's Python lacks, through the same
// whole-or-nothing file as the command line's images.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/Text.h"
#include "image/PngFile.h"
#include "python/Arguments.h"
#include "python/Bindings.h"

namespace tabletop::python {
namespace {

namespace py = pybind11;

void writePngFile(const py::array& array, const std::string& path) {
  if (!array.dtype().is(py::dtype::of<std::uint8_t>())) {
    throw py::type_error("write_png: image: expected an array of uint8, got dtype " +
                         py::str(array.dtype()).cast<std::string>());
  }
  if (array.ndim() != 3 || array.shape(2) != 3) {
    std::string shape;
    for (py::ssize_t k = 0; k < array.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(array.shape(k));
    throw py::value_error("write_png: image: expected shape (height, width, 3), got (" + shape + ")");
  }
  const py::ssize_t h = array.shape(0), w = array.shape(1);
  if (h < 1 || w < 1 || h > kMaxImageSide || w > kMaxImageSide) {
    throw py::value_error("write_png: image: expected sides from 1 to " + std::to_string(kMaxImageSide) + ", got " +
                          std::to_string(h) + " x " + std::to_string(w));
  }
  // As every output name of the command line's (io/AtomicFile).
  if (const auto unprintable = unprintableProblem(path)) {
    PyErr_SetString(PyExc_OSError, ("write_png: path: '" + shownText(path, 256) +
                                    "': expected a printable file name, got " + *unprintable).c_str());
    throw py::error_already_set();
  }
  const auto pixels = py::array_t<std::uint8_t, py::array::c_style>::ensure(array);
  Image image(static_cast<int>(w), static_cast<int>(h));
  std::memcpy(image.rgb.data(), pixels.data(), image.rgb.size());
  try {
    const py::gil_scoped_release nogil;
    writePng(image, path);
  } catch (const std::runtime_error& e) {
    PyErr_SetString(PyExc_OSError, (std::string("write_png: ") + e.what()).c_str());
    throw py::error_already_set();
  }
}

}  // namespace

void bindImages(py::module_& m) {
  m.def("write_png", &writePngFile, py::arg("image"), py::arg("path"),
        "Writes an image (height x width x 3 uint8, as render() returns) to path as a PNG. The file is written "
        "whole or not at all (a temporary file renamed into place); a name with a control character is refused. "
        "Raises TypeError or ValueError for a bad array, OSError when the file cannot be written.");
}

}  // namespace tabletop::python
