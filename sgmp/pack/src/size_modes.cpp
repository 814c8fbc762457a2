#include "sgmp/pack/size_modes.hpp"

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <numeric>

#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/parameter_error.hpp"

namespace sgmp {

namespace {

std::optional<double> parse_positive(std::string_view text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
        !std::isfinite(value) || !(value > 0.0)) {
        return std::nullopt;
    }
    return value;
}

}  // namespace

std::optional<std::vector<SizeMode>> parse_size_modes(std::string_view text) {
    std::vector<SizeMode> modes;
    while (true) {
        const std::size_t comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        const std::size_t colon = item.find(':');
        if (colon == std::string_view::npos) {
            return std::nullopt;
        }
        const std::size_t second = item.find(':', colon + 1);
        const auto size = parse_positive(item.substr(0, colon));
        const auto fraction = parse_positive(item.substr(colon + 1, second - colon - 1));
        if (!size || !fraction) {
            return std::nullopt;
        }
        SizeMode mode{*size, *fraction, std::nullopt};
        if (second != std::string_view::npos) {
            mode.density = parse_positive(item.substr(second + 1));
            if (!mode.density) {
                return std::nullopt;
            }
        }
        modes.push_back(mode);
        if (comma == std::string_view::npos) {
            return modes;
        }
        text.remove_prefix(comma + 1);
    }
}

std::string size_modes_to_string(const std::vector<SizeMode>& modes) {
    std::string text;
    for (const SizeMode& m : modes) {
        text += (text.empty() ? "" : ",") + format_number(m.relative_diameter) + ":" +
                format_number(m.fraction);
        if (m.density) {
            text += ":" + format_number(*m.density);
        }
    }
    return text;
}

const NameTable<FractionBasis, 3>& fraction_bases() {
    static constexpr NameTable<FractionBasis, 3> table{{{{FractionBasis::Number, "number"},
                                                         {FractionBasis::Volume, "volume"},
                                                         {FractionBasis::Mass, "mass"}}}};
    return table;
}

std::string_view to_string(FractionBasis basis) {
    return fraction_bases().name(basis);
}

std::optional<FractionBasis> parse_fraction_basis(std::string_view text) {
    return fraction_bases().parse(text);
}

bool is_lognormal(std::string_view text) {
    return text.starts_with("lognormal:");
}

std::vector<SizeMode> lognormal_modes(std::string_view text) {
    const std::string shown(text);
    const auto refuse = [&](const std::string& rule) -> void {
        throw ParameterError("size_distribution", shown, rule);
    };
    const std::string form =
        "must be lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]], e.g. lognormal:200:0.4:10:0.01:0.99";
    if (!is_lognormal(text)) {
        refuse(form);
    }
    std::vector<double> values;
    std::string_view rest = text.substr(std::string_view("lognormal:").size());
    while (true) {
        const std::size_t colon = rest.find(':');
        const std::string field(rest.substr(0, colon));
        double value = 0.0;
        const auto result = std::from_chars(field.data(), field.data() + field.size(), value);
        if (field.empty() || result.ec != std::errc() ||
            result.ptr != field.data() + field.size() || !std::isfinite(value)) {
            refuse(form);
        }
        values.push_back(value);
        if (colon == std::string_view::npos) {
            break;
        }
        rest.remove_prefix(colon + 1);
    }
    if (values.size() != 2 && values.size() != 3 && values.size() != 5) {
        refuse(form);
    }
    const double median = values[0];
    const double sigma = values[1];
    const double classes = values.size() >= 3 ? values[2] : 10.0;
    const double q_lo = values.size() == 5 ? values[3] : 0.01;
    const double q_hi = values.size() == 5 ? values[4] : 0.99;
    if (!(median > 0.0)) {
        refuse("MEDIAN must be positive");
    }
    if (!(sigma > 0.0) || sigma > 3.0) {
        refuse("SIGMA must lie in (0, 3]");
    }
    if (classes != std::floor(classes) || classes < 1.0 || classes > 1000.0) {
        refuse("CLASSES must be a whole number from 1 to 1000");
    }
    if (!(q_lo > 0.0) || !(q_hi < 1.0) || !(q_lo < q_hi)) {
        refuse("the quantiles must satisfy 0 < QLO < QHI < 1");
    }
    const boost::math::normal_distribution<double> normal;
    const auto n = static_cast<std::size_t>(classes);
    std::vector<double> diameters;
    for (std::size_t k = 0; k < n; ++k) {
        const double p =
            q_lo + (static_cast<double>(k) + 0.5) * (q_hi - q_lo) / static_cast<double>(n);
        diameters.push_back(median * std::exp(sigma * boost::math::quantile(normal, p)));
    }
    std::vector<SizeMode> modes;
    for (const double diameter : diameters) {
        modes.emplace_back(diameter / diameters.back(), 1.0 / static_cast<double>(n));
    }
    return modes;
}

std::string_view length_units() {
    return "m, cm, mm, um, nm";
}

std::optional<double> metres_per_unit(std::string_view unit) {
    return unit == "m"    ? std::optional(1.0)
           : unit == "cm" ? std::optional(1e-2)
           : unit == "mm" ? std::optional(1e-3)
           : unit == "um" ? std::optional(1e-6)
           : unit == "nm" ? std::optional(1e-9)
                          : std::nullopt;
}

std::optional<std::pair<double, std::string>> parse_physical_length(std::string_view text) {
    const auto space = text.find(' ');
    if (space == std::string_view::npos) {
        return std::nullopt;
    }
    const auto value = parse_csv_number<double>(std::string(text.substr(0, space)));
    const std::string unit(text.substr(space + 1));
    if (!value || !(*value > 0.0) || !std::isfinite(*value) || !metres_per_unit(unit)) {
        return std::nullopt;
    }
    return std::pair{*value, unit};
}

namespace {

/// The columns of a size-distribution CSV's header: their positions (−1: absent) and the
/// diameter's unit when a diameter_UNIT column states it.
struct DistributionColumns {
    std::size_t count = 0;
    int diameter = -1;
    int fraction = -1;
    int density = -1;
    std::string diameter_unit;
};

/// The header line `fields` (line `number` of `source`) as columns; throws InputError on an
/// unknown or repeated column, a unit not in length_units(), or no diameter or fraction.
DistributionColumns distribution_columns(const std::vector<std::string>& fields,
                                         const std::string& source, std::size_t number) {
    DistributionColumns columns;
    columns.count = fields.size();
    for (std::size_t c = 0; c < fields.size(); ++c) {
        std::string name = fields[c];
        if (name.rfind("diameter_", 0) == 0) {  // diameter_UNIT: the unit stated
            columns.diameter_unit = name.substr(9);
            if (!metres_per_unit(columns.diameter_unit)) {
                throw InputError(source, number,
                                 "column '" + name + "': the diameter's unit must be one of " +
                                     std::string(length_units()));
            }
            name = "diameter";
        }
        int* slot = name == "diameter"   ? &columns.diameter
                    : name == "fraction" ? &columns.fraction
                    : name == "density"  ? &columns.density
                                         : nullptr;
        if (slot == nullptr) {
            throw InputError(source, number,
                             "unknown column '" + name +
                                 "': the columns are diameter (or diameter_UNIT, UNIT "
                                 "one of " +
                                 std::string(length_units()) +
                                 "), fraction and optionally density");
        }
        if (*slot >= 0) {
            throw InputError(source, number, "names '" + name + "' twice");
        }
        *slot = static_cast<int>(c);
    }
    if (columns.diameter < 0 || columns.fraction < 0) {
        throw InputError(source, number,
                         "the header must name 'diameter' and 'fraction' (and "
                         "optionally 'density')");
    }
    return columns;
}

/// One species row `fields` (line `number` of `source`) as a mode of its own diameter (not
/// yet relative); throws InputError on a wrong field count or a value out of range.
SizeMode distribution_row(const std::vector<std::string>& fields,
                          const DistributionColumns& columns, const std::string& source,
                          std::size_t number) {
    if (fields.size() != columns.count) {
        throw InputError(source, number,
                         "has " + std::to_string(fields.size()) + " fields, the header " +
                             std::to_string(columns.count));
    }
    const auto value = [&](int column, const char* what) {
        const auto v = parse_csv_number<double>(fields[static_cast<std::size_t>(column)]);
        if (!v) {
            throw InputError(source, number,
                             std::string(what) + " '" + fields[static_cast<std::size_t>(column)] +
                                 "' is not a finite number");
        }
        return *v;
    };
    SizeMode mode{value(columns.diameter, "diameter"), value(columns.fraction, "fraction"),
                  std::nullopt};
    if (!(mode.relative_diameter > 0.0)) {
        throw InputError(source, number,
                         "diameter " + format_number(mode.relative_diameter) +
                             ": a diameter must be greater than 0");
    }
    if (mode.fraction < 0.0) {
        throw InputError(
            source, number,
            "fraction " + format_number(mode.fraction) + ": a fraction must not be negative");
    }
    if (columns.density >= 0) {
        mode.density = value(columns.density, "density");
        if (!(*mode.density > 0.0)) {
            throw InputError(
                source, number,
                "density " + format_number(*mode.density) + ": a density must be greater than 0");
        }
    }
    return mode;
}

/// The modes relative to the largest diameter (only ratios matter: the largest is 1);
/// returns that largest diameter. Throws InputError (at line `number`) when there is no
/// mode or every fraction is 0.
double make_relative(std::vector<SizeMode>& modes, const std::string& source, std::size_t number) {
    if (modes.empty()) {
        throw InputError(source, number, "holds no species row (a header, then one row each)");
    }
    double total = 0.0;
    double largest = 0.0;
    for (const SizeMode& m : modes) {
        total += m.fraction;
        largest = std::max(largest, m.relative_diameter);
    }
    if (!(total > 0.0)) {
        throw InputError(source, number, "every fraction is 0: at least one must be positive");
    }
    for (SizeMode& m : modes) {
        m.relative_diameter /= largest;
    }
    return largest;
}

}  // namespace

std::vector<SizeMode> parse_size_distribution_csv(std::string_view text, const std::string& source,
                                                  std::string* largest_diameter) {
    std::optional<DistributionColumns> columns;
    std::vector<SizeMode> modes;
    std::size_t number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++number;
        if (!line.empty() && line.back() == '\r') {
            line.remove_suffix(1);
        }
        if (line.find_first_not_of(" \t") == std::string_view::npos || line.front() == '#') {
            continue;
        }
        const auto fields = split_quoted_csv_line(line);
        if (!fields) {
            throw InputError(source, number, "a quoted field is not closed");
        }
        if (!columns) {
            columns = distribution_columns(*fields, source, number);
            continue;
        }
        modes.push_back(distribution_row(*fields, *columns, source, number));
    }
    const double largest = make_relative(modes, source, number);
    if (largest_diameter != nullptr && columns && !columns->diameter_unit.empty()) {
        *largest_diameter = format_number(largest) + " " + columns->diameter_unit;
    }
    return modes;
}

std::vector<SizeMode> number_fractions(const std::vector<SizeMode>& modes, FractionBasis basis) {
    std::vector<SizeMode> out = modes;
    double total = 0.0;
    for (SizeMode& m : out) {
        const double a3 = m.relative_diameter * m.relative_diameter * m.relative_diameter;
        if (basis == FractionBasis::Volume) {
            m.fraction /= a3;
        } else if (basis == FractionBasis::Mass) {
            if (!m.density) {
                throw ParameterError("fraction_basis", "mass",
                                     "needs a density for every species (a density column, "
                                     "or diameter:fraction:density modes)");
            }
            m.fraction /= *m.density * a3;
        }
        total += m.fraction;
    }
    for (SizeMode& m : out) {
        m.fraction /= total;
    }
    return out;
}

bool is_monodisperse(const std::vector<SizeMode>& modes) {
    return modes.size() == 1 && modes.front().relative_diameter == 1.0;
}

std::optional<double> unnormalised_total(const std::vector<SizeMode>& modes) {
    double total = 0.0;
    for (const SizeMode& m : modes) {
        total += m.fraction;
    }
    return std::abs(total - 1.0) > 1e-9 ? std::optional<double>(total) : std::nullopt;
}

double diameter_scale(std::size_t count, double phi_target, const std::vector<SizeMode>& modes) {
    double total = 0.0;
    double moment = 0.0;
    for (const SizeMode& m : modes) {
        total += m.fraction;
        moment += m.fraction * m.relative_diameter * m.relative_diameter * m.relative_diameter;
    }
    return std::cbrt(18.0 * phi_target * total /
                     (std::numbers::pi * static_cast<double>(count) * moment));
}

std::vector<std::size_t> mode_counts(std::size_t count, const std::vector<SizeMode>& modes) {
    double total = 0.0;
    for (const SizeMode& m : modes) {
        total += m.fraction;
    }
    // Largest remainder: floor of each share, the rest to the largest fractional parts.
    std::vector<std::size_t> counts(modes.size());
    std::vector<std::pair<double, std::size_t>> remainders;
    std::size_t assigned = 0;
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const double share = static_cast<double>(count) * modes[i].fraction / total;
        counts[i] = static_cast<std::size_t>(std::floor(share));
        assigned += counts[i];
        remainders.emplace_back(share - std::floor(share), i);
    }
    std::stable_sort(remainders.begin(), remainders.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t k = 0; assigned < count; ++k, ++assigned) {
        ++counts[remainders[k % remainders.size()].second];
    }
    return counts;
}

DrawnSizes draw_sizes(std::size_t count, double phi_target, const std::vector<SizeMode>& modes,
                      Random& rng, DropOrder order) {
    const double scale = diameter_scale(count, phi_target, modes);
    DrawnSizes drawn;
    if (is_monodisperse(modes)) {
        drawn.diameters.assign(count, scale);
        drawn.species.assign(count, 0);
        return drawn;
    }
    const std::vector<std::size_t> counts = mode_counts(count, modes);
    drawn.diameters.reserve(count);
    drawn.species.reserve(count);
    const bool blend = modes.size() > 1;
    if (order == DropOrder::Stratified) {
        for (const std::size_t i : stratified_sequence(counts)) {
            drawn.diameters.push_back(modes[i].relative_diameter * scale);
            drawn.species.push_back(blend ? static_cast<int>(i) + 1 : 0);
        }
        return drawn;
    }
    for (std::size_t i = 0; i < modes.size(); ++i) {
        drawn.diameters.insert(drawn.diameters.end(), counts[i],
                               modes[i].relative_diameter * scale);
        drawn.species.insert(drawn.species.end(), counts[i], blend ? static_cast<int>(i) + 1 : 0);
    }
    for (std::size_t i = drawn.diameters.size(); i > 1; --i) {
        const std::size_t j = rng.below(i);
        std::swap(drawn.diameters[i - 1], drawn.diameters[j]);
        std::swap(drawn.species[i - 1], drawn.species[j]);
    }
    return drawn;
}

std::vector<double> draw_diameters(std::size_t count, double phi_target,
                                   const std::vector<SizeMode>& modes, Random& rng) {
    return draw_sizes(count, phi_target, modes, rng).diameters;
}

}  // namespace sgmp
