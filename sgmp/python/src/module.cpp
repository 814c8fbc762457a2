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
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/version.hpp"

namespace py = pybind11;
using namespace sgmp::python;

namespace {

sgmp::Pack read_pack(const std::filesystem::path& path, std::optional<std::size_t> frame,
                     std::optional<double> radius) {
    if (!frame && !radius) {
        return sgmp::read_pack_file(path);
    }
    sgmp::ReadOptions options;
    options.frame = frame;
    options.radius = radius;
    return sgmp::read_pack_file(path, options).pack;
}

void write_pack(const py::object& pack, const std::filesystem::path& path, bool force,
                const std::optional<std::string>& format) {
    std::optional<sgmp::PackFormat> chosen =
        format ? sgmp::parse_pack_format(*format) : sgmp::format_from_extension(path);
    if (!chosen) {
        throw format
            ? sgmp::ParameterError("format", *format, "must be " + sgmp::pack_format_choices())
            : sgmp::ParameterError(
                  "path", path.string(),
                  "its ending names no format; give format= (" + sgmp::pack_format_choices() + ")");
    }
    sgmp::WriteOptions options;
    options.overwrite = force;
    sgmp::write_pack_as(path, pack_of(pack), *chosen, options);
}

}  // namespace

PYBIND11_MODULE(_sgmp, m) {
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
    m.def("read", &read_pack, py::arg("path"), py::arg("frame") = py::none(),
          py::arg("radius") = py::none(),
          "Reads a pack file: extended XYZ (frame: counted from 1, default the last), "
          "LAMMPS/LIGGGHTS dump custom or a LAMMPS data file; .gz transparently. radius "
          "replaces every radius (for species-only files). Raises ValueError (\"file:line: "
          "reason\") for malformed files.");
    m.def("write", &write_pack, py::arg("pack"), py::arg("path"), py::arg("force") = false,
          py::arg("format") = py::none(),
          "Writes a pack file atomically in the format named by format (xyz, xyz.gz, data, "
          "dump, vtk) or by the path's ending (.xyz, .xyz.gz, .data, .dump, .vtk); vtk also "
          "writes NAME.container.vtk. An existing file is replaced only with force=True "
          "(else OSError); a format that cannot carry the pack raises ValueError.");
}
