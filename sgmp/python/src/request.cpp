// sgmp.pack(...) and sgmp.arrange(...): keyword arguments named as the parameters in pack
// headers (the command-line options with dashes as underscores) fill an engine
// PackRequest whose own defaults stand for every option not given; the engine's
// validate() judges it. Errors are the libraries' ParameterError, raised as ValueError
// with its one-line text naming the keyword ("gap = banana: must be one of largest,
// random"; the command line shows the same as "--gap banana: ...").
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_parameters.hpp"
#include "sgmp/pack/bounded_file.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/size_modes.hpp"

namespace sgmp::python {
namespace {

using engine::PackRequest;

std::string shown(const py::handle& value) {
    return py::str(value).cast<std::string>();
}

/// The engine's error for a parameter: its keyword (the header name), the value, the rule.
ParameterError bad(std::string option, const py::handle& value, const std::string& rule) {
    std::replace(option.begin(), option.end(), '-', '_');
    return ParameterError(option, shown(value), rule);
}

/// The text of a Python value for the row, after the checks of its kind: numbers must be
/// int or float (not bool), whole numbers int, choices and text str, lists str or (for
/// sweep_stages) a sequence of whole numbers.
std::string text_of(const engine::PackParameter& row, const py::handle& value) {
    const bool is_bool = py::isinstance<py::bool_>(value);
    switch (row.kind) {
        case ValueKind::Number:
            if (is_bool ||
                !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value))) {
                throw bad(row.name, value, "must be a number");
            }
            return format_number(value.cast<double>());
        case ValueKind::Integer:
            if (is_bool || !py::isinstance<py::int_>(value)) {
                throw bad(row.name, value, row.rule);
            }
            return shown(value);  // decimal digits; the row clamps what its type cannot hold
        case ValueKind::List:
            if (row.name == "sweep_stages" && !py::isinstance<py::str>(value) &&
                py::isinstance<py::sequence>(value)) {
                std::string joined;
                for (const auto& item : value.cast<py::sequence>()) {
                    if (py::isinstance<py::bool_>(item) || !py::isinstance<py::int_>(item)) {
                        throw bad(row.name, value, row.rule);
                    }
                    joined += (joined.empty() ? "" : ",") + shown(item);
                }
                return joined;
            }
            [[fallthrough]];
        case ValueKind::Choice:
        case ValueKind::Text:
            if (!py::isinstance<py::str>(value)) {
                throw bad(row.name, value, "must be a string");
            }
            return value.cast<std::string>();
    }
    return {};
}

/// A size distribution given as a CSV file: the front end reads it, the engine parses it.
void read_size_distribution(PackRequest& r, const py::handle& value) {
    const std::string spec = value.cast<std::string>();
    if (!std::filesystem::is_regular_file(spec)) {
        throw bad("size_distribution", value,
                  "must name a readable file or be lognormal:MEDIAN:SIGMA[...]");
    }
    const std::string content =
        sgmp::read_bounded_file(spec, sgmp::kMaxSmallFileBytes, "a size distribution file");
    r.size_modes = sgmp::parse_size_distribution_csv(content, spec, &r.largest_diameter);
    r.size_distribution = spec;
}

/// Sets the row's value from a Python value; ValueError with the row's rule when refused.
void set(PackRequest& r, const engine::PackParameter& row, const py::handle& value) {
    const std::string typed = text_of(row, value);
    if (row.parse(r, typed)) {
        return;
    }
    if (row.name == "size_distribution") {
        read_size_distribution(r, value);
        return;
    }
    throw bad(row.name, value, row.rule);
}

const engine::PackParameter& row_named(std::string_view name) {
    return *engine::find_pack_parameter(name);
}

/// Positional arguments of their own: not keywords.
bool positional(const engine::PackParameter& row) {
    return row.name == "count" || row.name == "arrangement" || row.name == "seed";
}

PackRequest request_of(const py::handle& count, const py::handle& arrangement,
                       const py::handle& seed, const py::kwargs& options) {
    PackRequest request;
    set(request, row_named("count"), count);
    set(request, row_named("arrangement"), arrangement);
    if (!seed.is_none()) {
        set(request, row_named("seed"), seed);
    }
    if (options.contains("size_modes") && options.contains("size_distribution")) {
        throw bad("size_distribution", options["size_distribution"],
                  "give either size_modes or size_distribution, not both");
    }
    for (const auto& [key, value] : options) {
        const std::string name = py::str(key).cast<std::string>();
        const engine::PackParameter* row = engine::find_pack_parameter(name);
        if (row == nullptr || positional(*row) || name.find('-') != std::string::npos) {
            std::string known;
            for (const engine::PackParameter& r : engine::pack_parameters()) {
                known += (known.empty() ? "" : ", ") + r.name;
            }
            throw std::invalid_argument(name + ": not an option of sgmp.pack (options: " + known +
                                        ")");
        }
    }
    // In table order, whatever the order of the keywords: sweep_stages overrides
    // sweep_positions as on the command line.
    for (const engine::PackParameter& row : engine::pack_parameters()) {
        if (!positional(row) && options.contains(row.name.c_str())) {
            set(request, row, options[row.name.c_str()]);
        }
    }
    engine::validate(request);  // ParameterError naming the keyword
    // Fractions not summing to 1 are normalised, with a UserWarning as the command line's.
    const char* given = options.contains("size_distribution") ? "size_distribution"
                        : options.contains("size_modes")      ? "size_modes"
                                                              : nullptr;
    if (given != nullptr) {
        if (const auto total = unnormalised_total(request.size_modes)) {
            const std::string text =
                std::string(given) + " = " + py::str(options[given]).cast<std::string>() +
                ": fractions sum to " + format_number(*total) + "; normalised to 1";
            if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) != 0) {
                throw py::error_already_set();  // warnings turned into errors
            }
        }
    }
    return request;
}

}  // namespace

/// The kind of each pack parameter, by its header key: how sgmp.Pack.header types a value.
py::dict header_kinds() {
    py::dict kinds;
    for (const engine::PackParameter& row : engine::pack_parameters()) {
        const char* kind = "text";
        switch (row.kind) {
            case ValueKind::Number:
                kind = "number";
                break;
            case ValueKind::Integer:
                kind = "integer";
                break;
            case ValueKind::Choice:
                kind = "choice";
                break;
            case ValueKind::List:
                kind = "list";
                break;
            case ValueKind::Text:
                break;
        }
        kinds[py::str(header_key(row))] = kind;
    }
    return kinds;
}

void bind_making(py::module_& m) {
    m.def("header_kinds", &header_kinds,
          "The kind of every pack parameter's header value, by header key: number, integer, "
          "choice, list or text (the parameter table's).");
    m.def(
        "pack",
        [](const py::object& count, const py::object& arrangement, const py::object& seed,
           const py::object& progress, const py::kwargs& options) {
            const PackRequest request = request_of(count, arrangement, seed, options);
            if (!progress.is_none() && !PyCallable_Check(progress.ptr())) {
                throw bad("progress", progress, "must be a callable or None");
            }
            // Ctrl-C stops the engine at its next progress call (a KeyboardInterrupt now,
            // not when the call ends): the callbacks take the interpreter's lock to look at
            // its signals and to call `progress(phase, done, total)`.
            const auto report = [&](const char* phase, std::size_t done, std::size_t total) {
                py::gil_scoped_acquire locked;
                if (PyErr_CheckSignals() != 0) {
                    throw py::error_already_set();
                }
                if (!progress.is_none()) {
                    progress(phase, done, total);
                }
            };
            py::gil_scoped_release unlocked;
            return engine::make_pack(
                request,
                [&](std::size_t placed, std::size_t total) { report("deposition", placed, total); },
                nullptr,
                [&](const engine::RelaxProgress& r) {
                    using Phase = engine::RelaxProgress::Phase;
                    if (r.phase == Phase::Settling || r.phase == Phase::Dynamics) {
                        report("settling", static_cast<std::size_t>(r.settle_iteration), 0);
                    } else {
                        report(r.phase == Phase::Soft ? "relaxation" : "clearing",
                               static_cast<std::size_t>(r.steps), 0);
                    }
                });
        },
        py::arg("count"), py::arg("arrangement"), py::arg("seed") = py::none(),
        py::arg("progress") = py::none(),
        "Packs `count` spheres from `arrangement` (single-column, small-dense, large-dense, "
        "loose-random) with the protocol. Every option of `sgmp pack` is a keyword, dashes as "
        "underscores (circle_factor=50, gap='random', sweep_stages='8,120,720', "
        "relax='frictionless', relax_stiffness=2e3, ...); an option not given keeps the "
        "engine's default, and seed=None its default seed. The same options give the same "
        "pack as `sgmp pack`, bit for bit. Raises ValueError with the command line's message.");
    m.def(
        "arrange",
        [](const py::object& count, const py::object& arrangement, const py::object& seed,
           const py::kwargs& options) {
            return engine::make_start_pack(request_of(count, arrangement, seed, options));
        },
        py::arg("count"), py::arg("arrangement"), py::arg("seed") = py::none(),
        "The starting arrangement itself (as `sgmp arrange`); options as sgmp.pack.");
}

}  // namespace sgmp::python
