#include "sgmp/engine/relax_params.hpp"

#include <cmath>

#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::engine {

void validate(const RelaxParams& p) {
    if (!(p.stiffness >= 1e2) || !(p.stiffness <= 1e12)) {
        throw ParameterError("relax_stiffness", format_number(p.stiffness),
                             "must be in [100, 1e12] (m*g/d)");
    }
    if (!(p.stiffness_factor >= 1.0) || !(p.stiffness_factor <= 1e6)) {
        throw ParameterError("relax_stiffness_factor", format_number(p.stiffness_factor),
                             "must be in [1, 1e6]");
    }
    if (p.stages < 1 || p.stages > 10) {
        throw ParameterError("relax_stages", std::to_string(p.stages), "must be 1 to 10");
    }
    if (!(p.stiffness * std::pow(p.stiffness_factor, p.stages - 1) <= 1e12)) {
        throw ParameterError("relax_stages", std::to_string(p.stages),
                             "the last stage's stiffness must not exceed 1e12 m*g/d");
    }
    if (!(p.shell >= 0.0) || !(p.shell <= 0.01)) {
        throw ParameterError("relax_shell", format_number(p.shell), "must be in [0, 0.01]");
    }
    if (!(p.force_tolerance > 0.0) || !(p.force_tolerance <= 1.0)) {
        throw ParameterError("relax_force_tolerance", format_number(p.force_tolerance),
                             "must be in (0, 1] (m*g)");
    }
    if (!(p.time > 0.0) || !(p.time <= 1e4)) {
        throw ParameterError("relax_time", format_number(p.time), "must be in (0, 10000]");
    }
    if (!(p.crossings > 0.0) || !(p.crossings <= 1e4)) {
        throw ParameterError("relax_crossings", format_number(p.crossings),
                             "must be in (0, 10000]");
    }
    if (!(p.friction >= 0.0) || !(p.friction <= 10.0)) {
        throw ParameterError("relax_friction", format_number(p.friction), "must be in [0, 10]");
    }
    if (p.settle_limit < 1 || p.settle_limit > 1000000) {
        throw ParameterError("relax_settle_limit", std::to_string(p.settle_limit),
                             "must be between 1 and 1000000");
    }
    if (!(p.tangential_ratio > 0.0) || !(p.tangential_ratio <= 1.0)) {
        throw ParameterError("relax_tangential_ratio", format_number(p.tangential_ratio),
                             "must be in (0, 1]");
    }
}

const NameTable<RelaxMode, 3>& relax_modes() {
    static constexpr NameTable<RelaxMode, 3> table{{{{RelaxMode::None, "none"},
                                                     {RelaxMode::Frictionless, "frictionless"},
                                                     {RelaxMode::Frictional, "frictional"}}}};
    return table;
}

std::string_view to_string(RelaxMode mode) {
    return relax_modes().name(mode);
}

std::optional<RelaxMode> parse_relax_mode(std::string_view text) {
    return relax_modes().parse(text);
}

void record(const RelaxParams& p, Metadata& m) {
    if (p.mode == RelaxMode::None) {
        return;
    }
    m.set("relax", std::string(to_string(p.mode)));
    m.set_number("relax_stiffness", p.stiffness);
    m.set_number("relax_stiffness_factor", p.stiffness_factor);
    m.set_integer("relax_stages", p.stages);
    m.set_number("relax_shell", p.shell);
    m.set_number("relax_force_tolerance", p.force_tolerance);
    m.set_number("relax_time", p.time);
    m.set_number("relax_crossings", p.crossings);
    m.set_integer("relax_settle_limit", p.settle_limit);
    if (p.mode == RelaxMode::Frictional) {
        m.set_number("relax_friction", p.friction);
        m.set_number("relax_tangential_ratio", p.tangential_ratio);
    }
}

}  // namespace sgmp::engine
