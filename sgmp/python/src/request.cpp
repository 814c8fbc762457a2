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
#include "sgmp/engine/size_modes.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/parameter_error.hpp"

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

double number(const py::handle& value, const std::string& option) {
    if (py::isinstance<py::bool_>(value) ||
        !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value))) {
        throw bad(option, value, "must be a number");
    }
    return value.cast<double>();
}

long long integer(const py::handle& value, const std::string& option) {
    if (py::isinstance<py::bool_>(value) || !py::isinstance<py::int_>(value)) {
        throw bad(option, value, "must be a whole number");
    }
    try {
        return value.cast<long long>();
    } catch (const py::cast_error&) {
        throw bad(option, value, "must be a whole number of at most 64 bits");
    }
}

std::string text(const py::handle& value, const std::string& option) {
    if (!py::isinstance<py::str>(value)) {
        throw bad(option, value, "must be a string");
    }
    return value.cast<std::string>();
}

template <class T>
T choice(std::optional<T> parsed, const std::string& option, const py::handle& value,
         std::string_view choices) {
    if (!parsed) {
        throw bad(option, value, "must be one of " + std::string(choices));
    }
    return *parsed;
}

/// "8,120,720" or a sequence of whole numbers.
std::vector<int> stages(const py::handle& value) {
    std::string typed;
    if (py::isinstance<py::str>(value)) {
        typed = value.cast<std::string>();
    } else if (py::isinstance<py::sequence>(value)) {
        for (const auto& item : value.cast<py::sequence>()) {
            typed += (typed.empty() ? "" : ",") + std::to_string(integer(item, "sweep-stages"));
        }
    }
    const auto parsed = engine::parse_stages(typed);
    if (!parsed) {
        throw bad("sweep-stages", value, "must be comma-separated whole numbers, e.g. 8,120,720");
    }
    return *parsed;
}

using Setter = std::function<void(PackRequest&, const py::handle&)>;

/// Every option of `sgmp pack` but count, arrangement, seed (arguments of their own) and
/// the file options, keyed by its keyword.
const std::map<std::string, Setter>& setters() {
    using engine::parse_contact_model;
    static const std::map<std::string, Setter> table = {
        {"phi_target", [](PackRequest& r, auto v) { r.phi_target = number(v, "phi-target"); }},
        {"size_modes",
         [](PackRequest& r, auto v) {
             const auto modes = engine::parse_size_modes(text(v, "size-modes"));
             if (!modes) {
                 throw bad("size-modes", v,
                           "must be positive diameter:fraction[:density] items, e.g. "
                           "1:0.7,0.5:0.3");
             }
             r.size_modes = *modes;
         }},
        {"size_distribution",
         [](PackRequest& r, auto v) {
             // lognormal:MEDIAN:SIGMA[...] or a CSV file (header diameter,fraction[,density]),
             // read here: the front end opens files, the engine parses their text.
             const std::string spec = text(v, "size-distribution");
             if (engine::is_lognormal(spec)) {
                 r.size_modes = engine::lognormal_modes(spec);
             } else {
                 std::ifstream in(spec, std::ios::binary);
                 if (!std::filesystem::is_regular_file(spec) || !in) {
                     throw bad("size-distribution", v,
                               "must name a readable file or be lognormal:MEDIAN:SIGMA[...]");
                 }
                 std::ostringstream content;
                 content << in.rdbuf();
                 r.size_modes = engine::parse_size_distribution_csv(content.str(), spec);
             }
             r.size_distribution = spec;
         }},
        {"fraction_basis",
         [](PackRequest& r, auto v) {
             r.fraction_basis = choice(engine::parse_fraction_basis(text(v, "fraction-basis")),
                                       "fraction-basis", v, engine::fraction_bases().choices());
         }},
        {"circle_factor",
         [](PackRequest& r, auto v) { r.protocol.circle_factor = number(v, "circle-factor"); }},
        {"sweep_positions",
         [](PackRequest& r, auto v) {
             r.protocol.sweep_stages = {static_cast<int>(integer(v, "sweep-positions"))};
         }},
        {"sweep_stages", [](PackRequest& r, auto v) { r.protocol.sweep_stages = stages(v); }},
        {"lower_neighbours",
         [](PackRequest& r, auto v) {
             r.protocol.lower_neighbours = static_cast<int>(integer(v, "lower-neighbours"));
         }},
        {"gap",
         [](PackRequest& r, auto v) {
             r.protocol.gap = choice(engine::parse_gap_rule(text(v, "gap")), "gap", v,
                                     engine::gap_rules().choices());
         }},
        {"fall",
         [](PackRequest& r, auto v) {
             r.protocol.fall = choice(engine::parse_fall_mode(text(v, "fall")), "fall", v,
                                      engine::fall_modes().choices());
         }},
        {"fall_step",
         [](PackRequest& r, auto v) { r.protocol.fall_step = number(v, "fall-step"); }},
        {"contact",
         [](PackRequest& r, auto v) {
             r.protocol.contact = choice(parse_contact_model(text(v, "contact")), "contact", v,
                                         engine::contact_models().choices());
         }},
        {"momentum", [](PackRequest& r, auto v) { r.protocol.momentum = number(v, "momentum"); }},
        {"walls",
         [](PackRequest& r, auto v) {
             r.protocol.walls = choice(engine::parse_wall_rule(text(v, "walls")), "walls", v,
                                       engine::wall_rules().choices());
         }},
        {"stall_moves",
         [](PackRequest& r, auto v) {
             r.protocol.stall_moves = static_cast<long>(integer(v, "stall-moves"));
         }},
        {"max_moves",
         [](PackRequest& r, auto v) {
             r.protocol.max_moves = static_cast<long>(integer(v, "max-moves"));
         }},
        {"relax",
         [](PackRequest& r, auto v) {
             r.relax.mode = choice(engine::parse_relax_mode(text(v, "relax")), "relax", v,
                                   engine::relax_modes().choices());
         }},
        {"relax_stiffness",
         [](PackRequest& r, auto v) { r.relax.stiffness = number(v, "relax-stiffness"); }},
        {"relax_stiffness_factor",
         [](PackRequest& r, auto v) {
             r.relax.stiffness_factor = number(v, "relax-stiffness-factor");
         }},
        {"relax_stages",
         [](PackRequest& r, auto v) {
             r.relax.stages = static_cast<int>(integer(v, "relax-stages"));
         }},
        {"relax_shell", [](PackRequest& r, auto v) { r.relax.shell = number(v, "relax-shell"); }},
        {"relax_force_tolerance",
         [](PackRequest& r, auto v) {
             r.relax.force_tolerance = number(v, "relax-force-tolerance");
         }},
        {"relax_time", [](PackRequest& r, auto v) { r.relax.time = number(v, "relax-time"); }},
        {"relax_crossings",
         [](PackRequest& r, auto v) { r.relax.crossings = number(v, "relax-crossings"); }},
        {"relax_friction",
         [](PackRequest& r, auto v) { r.relax.friction = number(v, "relax-friction"); }},
        {"relax_settle_limit",
         [](PackRequest& r, auto v) {
             const long long limit = integer(v, "relax-settle-limit");
             // Out of int's range: a value validate() refuses, not one that wraps.
             r.relax.settle_limit = static_cast<int>(std::clamp<long long>(limit, 0, 1000001));
         }},
    };
    return table;
}

PackRequest request_of(const py::handle& count, const py::handle& arrangement,
                       const py::handle& seed, const py::kwargs& options) {
    PackRequest request;
    const long long n = integer(count, "count");
    if (n < 1 || n > static_cast<long long>(sgmp::kMaxCount)) {
        throw bad("count", count, "must be between 1 and " + std::to_string(sgmp::kMaxCount));
    }
    request.count = static_cast<std::size_t>(n);
    request.arrangement = choice(engine::parse_arrangement(text(arrangement, "arrangement")),
                                 "arrangement", arrangement, engine::arrangement_names());
    if (!seed.is_none()) {
        const std::string typed = py::isinstance<py::int_>(seed) && !py::isinstance<py::bool_>(seed)
                                      ? shown(seed)
                                      : std::string("?");
        if (const std::string rule = seed_rule(typed); !rule.empty()) {
            throw bad("seed", seed, rule);
        }
        request.seed = seed.cast<std::uint64_t>();
    }
    if (options.contains("size_modes") && options.contains("size_distribution")) {
        throw bad("size-distribution", options["size_distribution"],
                  "give either size_modes or size_distribution, not both");
    }
    for (const auto& [key, value] : options) {
        const std::string name = py::str(key).cast<std::string>();
        const auto setter = setters().find(name);
        if (setter == setters().end()) {
            std::string known;
            for (const auto& [option, unused] : setters()) {
                known += (known.empty() ? "" : ", ") + option;
            }
            throw std::invalid_argument(name +
                                        ": not an option of sgmp.pack (options: count, "
                                        "arrangement, seed, " +
                                        known + ")");
        }
        setter->second(request, value);
    }
    engine::validate(request);  // ParameterError naming the keyword
    return request;
}

}  // namespace

void bind_making(py::module_& m) {
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
                    if (r.phase == Phase::Settling) {
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
