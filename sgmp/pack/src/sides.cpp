#include "sgmp/pack/sides.hpp"

#include "sgmp/pack/metadata.hpp"

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

std::string periodic_cell_rule(double largest_diameter, double cell) {
    const double most = cell / kPeriodicCellDiameters;
    if (largest_diameter <= most) {
        return {};
    }
    return "the largest diameter " + format_number(largest_diameter) + " must fit the " +
           format_number(cell) + "-wide periodic cell at least " +
           format_number(kPeriodicCellDiameters) + " times across (at most " + format_number(most) +
           "; more particles or a smaller size ratio)";
}

}  // namespace sgmp
