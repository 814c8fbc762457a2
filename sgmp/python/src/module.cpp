// The Python module `sgmp`: pack making, pack files and metrics over the C++ libraries.
// Errors keep the libraries' one-line texts: bad parameters (ParameterError, "name =
// value: rule" with the keyword as name) and malformed files raise ValueError, failed
// reads and writes (an existing file without force=True) OSError.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <stdexcept>

#include "bindings.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/version.hpp"

namespace py = pybind11;
using namespace sgmp::python;

PYBIND11_MODULE(sgmp, m) {
    m.doc() =
        "SGMP sphere packs: make them (pack, arrange), read and write pack files (read, write) "
        "and measure them (measure). Axes: X left-right, Y up, Z front-back; lengths in units of "
        "the control volume's side.";
    m.attr("__version__") = sgmp::version();
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) {
                std::rethrow_exception(error);
            }
        } catch (const sgmp::InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const std::invalid_argument& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const std::runtime_error& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        }
    });
    bind_pack(m);
    bind_making(m);
    bind_measure(m);
    m.def(
        "read", [](const std::filesystem::path& path) { return sgmp::read_pack_file(path); },
        py::arg("path"),
        "Reads a pack file (extended XYZ or LAMMPS/LIGGGHTS dump custom, .gz transparently). "
        "Raises ValueError (\"file:line: reason\") for malformed files.");
    m.def(
        "write",
        [](const py::object& pack, const std::filesystem::path& path, bool force) {
            sgmp::write_pack_file(path, pack_of(pack), force);
        },
        py::arg("pack"), py::arg("path"), py::arg("force") = false,
        "Writes a pack file atomically (extended XYZ, gzip when the name ends in .gz); an "
        "existing file is replaced only with force=True (else OSError).");
}
