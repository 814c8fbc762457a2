#include "sgmp/engine/size_modes.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <numeric>

#include "sgmp/pack/metadata.hpp"

namespace sgmp::engine {

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
        const auto size = parse_positive(item.substr(0, colon));
        const auto fraction = parse_positive(item.substr(colon + 1));
        if (!size || !fraction) {
            return std::nullopt;
        }
        modes.push_back(SizeMode{*size, *fraction});
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
    }
    return text;
}

bool is_monodisperse(const std::vector<SizeMode>& modes) {
    return modes.size() == 1 && modes.front().relative_diameter == 1.0;
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

std::vector<double> draw_diameters(std::size_t count, double phi_target,
                                   const std::vector<SizeMode>& modes, Random& rng) {
    const double scale = diameter_scale(count, phi_target, modes);
    if (is_monodisperse(modes)) {
        return std::vector<double>(count, scale);
    }
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
    std::vector<double> diameters;
    diameters.reserve(count);
    for (std::size_t i = 0; i < modes.size(); ++i) {
        diameters.insert(diameters.end(), counts[i], modes[i].relative_diameter * scale);
    }
    for (std::size_t i = diameters.size(); i > 1; --i) {
        std::swap(diameters[i - 1], diameters[rng.below(i)]);
    }
    return diameters;
}

}  // namespace sgmp::engine
