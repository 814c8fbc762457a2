#include "sgmp/pack/atom_types.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "text_fields.hpp"

namespace sgmp {
namespace {

/// Mode diameters a_k·D·L (L the output frame's length scale, output_frame.hpp, else 1:
/// the recorded D is in control-volume sides); empty when the keys are absent or malformed.
std::vector<double> mode_diameters(const Pack& pack) {
    const auto text = pack.metadata.get("size_modes");
    const auto scale = pack.metadata.get("diameter");
    const auto unscaled = scale ? detail::parse_double(*scale) : std::nullopt;
    const auto length = pack.metadata.get("length_scale");
    const auto factor = length ? detail::parse_double(*length) : std::optional<double>(1.0);
    if (!text || !unscaled || !factor) {
        return {};
    }
    const std::optional<double> d = *unscaled * *factor;
    std::vector<double> modes;
    std::stringstream in(*text);
    std::string item;
    while (std::getline(in, item, ',')) {
        const auto a = detail::parse_double(item.substr(0, item.find(':')));
        if (!a) {
            return {};
        }
        modes.push_back(*a * *d);
    }
    return modes;
}

}  // namespace

AtomTypes atom_types(const Pack& pack) {
    const std::vector<double> modes = mode_diameters(pack);
    AtomTypes types;
    types.count = modes.empty() ? 1 : static_cast<int>(modes.size());
    types.type.reserve(pack.particles.size());
    for (const auto& p : pack.particles) {
        std::size_t best = 0;
        for (std::size_t k = 1; k < modes.size(); ++k) {
            if (std::abs(2.0 * p.radius - modes[k]) < std::abs(2.0 * p.radius - modes[best])) {
                best = k;
            }
        }
        types.type.push_back(static_cast<int>(best) + 1);
    }
    return types;
}

}  // namespace sgmp
