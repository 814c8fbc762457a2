// The Python module `sgmp`: pack making, pack files and metrics over the C++ libraries.
// Errors keep the libraries' one-line texts: bad parameters (ParameterError, "name =
// value: rule" with the keyword as name) and malformed files raise ValueError, failed
// reads and writes (an existing file without force=True) OSError.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <stdexcept>

#include "bindings.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/output_frame.hpp"
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

/// The output frame of write()'s keywords (output_frame.hpp), each checked.
sgmp::OutputFrame frame_of(const std::string& up, std::optional<double> length_scale,
                           const std::optional<std::string>& length_unit,
                           std::optional<double> density) {
    sgmp::OutputFrame frame;
    if (up != "y" && up != "z") {
        throw sgmp::ParameterError("up", up, "must be y or z");
    }
    frame.up = up == "z" ? sgmp::UpAxis::Z : sgmp::UpAxis::Y;
    const auto positive = [](const char* name, double value) {
        if (!(value > 0.0 && std::isfinite(value))) {
            throw sgmp::ParameterError(name, sgmp::format_number(value),
                                       "must be a finite number > 0");
        }
    };
    if (length_scale.has_value() != length_unit.has_value()) {
        throw length_scale
            ? sgmp::ParameterError("length_scale", sgmp::format_number(*length_scale),
                                   "needs length_unit (the unit it is in)")
            : sgmp::ParameterError("length_unit", *length_unit,
                                   "needs length_scale (one control-volume "
                                   "side in that unit)");
    }
    if (length_scale) {
        positive("length_scale", *length_scale);
        if (length_unit->empty() || length_unit->size() > 32 ||
            length_unit->find_first_of(" \t\r\n\"'=#") != std::string::npos) {
            throw sgmp::ParameterError("length_unit", *length_unit,
                                       "must be 1 to 32 characters, no blank, quote, = or #");
        }
        frame.length_scale = *length_scale;
        frame.length_unit = *length_unit;
    }
    if (density) {
        positive("density", *density);
        frame.density = *density;
    }
    return frame;
}

void write_pack(const py::object& pack, const std::filesystem::path& path, bool force,
                const std::optional<std::string>& format, const std::string& up,
                std::optional<double> length_scale, const std::optional<std::string>& length_unit,
                std::optional<double> density) {
    const sgmp::OutputFrame frame = frame_of(up, length_scale, length_unit, density);
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
    sgmp::write_pack_as(path, sgmp::in_output_frame(pack_of(pack), frame), *chosen, options);
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
        } catch (const sgmp::FileExists& e) {  // Python's spelling of --force
            const std::string text = e.path().string() + ": exists; pass force=True to replace it";
            PyErr_SetString(PyExc_FileExistsError, text.c_str());
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
          py::arg("format") = py::none(), py::kw_only(), py::arg("up") = "y",
          py::arg("length_scale") = py::none(), py::arg("length_unit") = py::none(),
          py::arg("density") = py::none(),
          "Writes a pack file atomically in the format named by format (xyz, xyz.gz, data, "
          "dump, vtk, vtp) or by the path's ending (.xyz, .xyz.gz, .data, .dump, .vtk, .vtp); "
          "vtk and vtp also write NAME.container.vtk/.vtp. up='z' writes z up (each centre "
          "(x, y, z) as (x, -z, y)); length_scale with length_unit writes lengths in that unit, "
          "one control-volume side being length_scale; density is a data file's density "
          "column (as sgmp convert --up, --length-scale, --length-unit, --density; reading "
          "the file back turns it y-up again). An existing file is replaced only with "
          "force=True (else OSError); a format that cannot carry the pack or a bad keyword "
          "raises ValueError.");
}
