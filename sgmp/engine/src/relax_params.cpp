#include "sgmp/engine/relax_params.hpp"

namespace sgmp::engine {

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

}  // namespace sgmp::engine
