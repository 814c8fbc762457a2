#include "sgmp/batch/parameters.hpp"

#include <algorithm>
#include <charconv>
#include <optional>
#include <stdexcept>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::batch {
namespace {

using engine::PackRequest;

[[noreturn]] void refuse(const std::string& name, const std::string& value,
                         const std::string& rule) {
    throw ParameterError(name, value, rule);
}

template <class T>
T number(const std::string& name, const std::string& text) {
    T value{};
    const auto* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (text.empty() || result.ec != std::errc() || result.ptr != end) {
        refuse(name, text, std::is_integral_v<T> ? "must be a whole number" : "must be a number");
    }
    return value;
}

template <class T>
T choice(std::optional<T> parsed, const std::string& name, const std::string& text,
         const std::string& choices) {
    if (!parsed) {
        refuse(name, text, "must be one of " + choices);
    }
    return *parsed;
}

void apply(PackRequest& r, const std::string& name, const std::string& v) {
    auto& p = r.protocol;
    auto& x = r.relax;
    if (name == "count") {
        const auto count = number<long long>(name, v);
        if (count < 1 || count > static_cast<long long>(kMaxCount)) {
            refuse(name, v, "must be between 1 and " + std::to_string(kMaxCount));
        }
        r.count = static_cast<std::size_t>(count);
    } else if (name == "arrangement") {
        r.arrangement =
            choice(engine::parse_arrangement(v), name, v, std::string(engine::arrangement_names()));
    } else if (name == "phi_target") {
        r.phi_target = number<double>(name, v);
    } else if (name == "size_modes") {
        r.size_modes = choice(engine::parse_size_modes(v), name, v,
                              "positive diameter:fraction[:density] items, e.g. 1:0.7,0.5:0.3");
    } else if (name == "fraction_basis") {
        r.fraction_basis =
            choice(engine::parse_fraction_basis(v), name, v, engine::fraction_bases().choices());
    } else if (name == "circle_factor") {
        p.circle_factor = number<double>(name, v);
    } else if (name == "sweep_positions") {
        p.sweep_stages = {number<int>(name, v)};  // a later sweep_stages overrides it
    } else if (name == "sweep_stages") {
        if (!v.empty()) {
            p.sweep_stages = choice(engine::parse_stages(v), name, v,
                                    "comma-separated whole numbers, e.g. 8,120,720");
        }
    } else if (name == "lower_neighbours") {
        p.lower_neighbours = number<int>(name, v);
    } else if (name == "gap") {
        p.gap = choice(engine::parse_gap_rule(v), name, v, engine::gap_rules().choices());
    } else if (name == "fall") {
        p.fall = choice(engine::parse_fall_mode(v), name, v, engine::fall_modes().choices());
    } else if (name == "fall_step") {
        p.fall_step = number<double>(name, v);
    } else if (name == "contact") {
        p.contact =
            choice(engine::parse_contact_model(v), name, v, engine::contact_models().choices());
    } else if (name == "momentum") {
        p.momentum = number<double>(name, v);
    } else if (name == "walls") {
        p.walls = choice(engine::parse_wall_rule(v), name, v, engine::wall_rules().choices());
    } else if (name == "stall_moves") {
        p.stall_moves = number<long>(name, v);
    } else if (name == "max_moves") {
        p.max_moves = number<long>(name, v);
    } else if (name == "relax") {
        x.mode = choice(engine::parse_relax_mode(v), name, v, engine::relax_modes().choices());
    } else if (name == "relax_stiffness") {
        x.stiffness = number<double>(name, v);
    } else if (name == "relax_stiffness_factor") {
        x.stiffness_factor = number<double>(name, v);
    } else if (name == "relax_stages") {
        x.stages = number<int>(name, v);
    } else if (name == "relax_shell") {
        x.shell = number<double>(name, v);
    } else if (name == "relax_force_tolerance") {
        x.force_tolerance = number<double>(name, v);
    } else if (name == "relax_time") {
        x.time = number<double>(name, v);
    } else if (name == "relax_crossings") {
        x.crossings = number<double>(name, v);
    } else if (name == "relax_friction") {
        x.friction = number<double>(name, v);
    }
}

std::vector<Parameter> make_parameters() {
    const PackRequest d;
    const auto& p = d.protocol;
    const auto& x = d.relax;
    const auto n = [](double v) { return format_number(v); };
    const auto i = [](long long v) { return std::to_string(v); };
    return {
        {"count", "", false},
        {"arrangement", "", false},
        {"phi_target", n(d.phi_target), false},
        {"size_modes", "1:1", true},
        {"fraction_basis", std::string(engine::to_string(d.fraction_basis)), false},
        {"circle_factor", n(p.circle_factor), false},
        {"sweep_positions", i(p.sweep_stages.front()), false},
        {"sweep_stages", "", true},
        {"lower_neighbours", i(p.lower_neighbours), false},
        {"gap", std::string(engine::to_string(p.gap)), false},
        {"fall", std::string(engine::to_string(p.fall)), false},
        {"fall_step", n(p.fall_step), false},
        {"contact", std::string(engine::to_string(p.contact)), false},
        {"momentum", n(p.momentum), false},
        {"walls", std::string(engine::to_string(p.walls)), false},
        {"stall_moves", i(p.stall_moves), false},
        {"max_moves", i(p.max_moves), false},
        {"relax", std::string(engine::to_string(x.mode)), false},
        {"relax_stiffness", n(x.stiffness), false},
        {"relax_stiffness_factor", n(x.stiffness_factor), false},
        {"relax_stages", i(x.stages), false},
        {"relax_shell", n(x.shell), false},
        {"relax_force_tolerance", n(x.force_tolerance), false},
        {"relax_time", n(x.time), false},
        {"relax_crossings", n(x.crossings), false},
        {"relax_friction", n(x.friction), false},
    };
}

}  // namespace

const std::vector<Parameter>& parameters() {
    static const std::vector<Parameter> table = make_parameters();
    return table;
}

std::size_t parameter_index(std::string_view name) {
    std::string key(name);
    std::replace(key.begin(), key.end(), '-', '_');
    const auto& table = parameters();
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (table[i].name == key) {
            return i;
        }
    }
    return std::string::npos;
}

engine::PackRequest to_request(const ParameterValues& values, std::uint64_t seed) {
    const auto& table = parameters();
    if (values.size() != table.size()) {
        throw std::invalid_argument("a job needs one value per parameter");
    }
    PackRequest request;
    request.seed = seed;
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (table[i].name != "sweep_stages" || !values[i].empty()) {
            apply(request, table[i].name, values[i]);
        }
    }
    engine::validate(request);  // ParameterError, named as headers do: the front end spells it
    return request;
}

}  // namespace sgmp::batch
