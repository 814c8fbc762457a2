#include "sgmp/pack/sides.hpp"

namespace sgmp {

const NameTable<Sides, 2>& sides_names() {
    static constexpr NameTable<Sides, 2> table{
        {{{Sides::Walls, "walls"}, {Sides::Periodic, "periodic"}}}};
    return table;
}

std::string_view to_string(Sides sides) {
    return sides_names().name(sides);
}

std::optional<Sides> parse_sides(std::string_view text) {
    return sides_names().parse(text);
}

}  // namespace sgmp
