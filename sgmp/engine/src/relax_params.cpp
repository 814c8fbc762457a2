#include "sgmp/engine/relax_params.hpp"

namespace sgmp::engine {

const NameTable<RelaxMode, 3>& relax_modes() {
    static constexpr NameTable<RelaxMode, 3> table{{{{RelaxMode::None, "none"},
                                                     {RelaxMode::Frictionless, "frictionless"},
                                                     {RelaxMode::Frictional, "frictional"}}}};
    return table;
}

const NameTable<RelaxSettle, 2>& relax_settles() {
    static constexpr NameTable<RelaxSettle, 2> table{
        {{{RelaxSettle::Lp, "lp"}, {RelaxSettle::Dynamics, "dynamics"}}}};
    return table;
}

RelaxSchedule relax_schedule(const RelaxParams& params) {
    const bool frictionless = params.mode == RelaxMode::Frictionless;
    RelaxSchedule schedule;
    schedule.stiffness = params.stiffness.value_or(frictionless ? 2e4 : 2e3);
    schedule.stages = params.stages.value_or(frictionless ? 1 : 5);
    schedule.time = params.time.value_or(frictionless ? 200.0 : 5.0);
    return schedule;
}

std::string_view to_string(RelaxMode mode) {
    return relax_modes().name(mode);
}

std::optional<RelaxMode> parse_relax_mode(std::string_view text) {
    return relax_modes().parse(text);
}

}  // namespace sgmp::engine
