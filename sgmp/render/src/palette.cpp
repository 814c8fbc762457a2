#include "sgmp/render/palette.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sgmp::render {
namespace {

constexpr Rgb from_hex(unsigned hex) {
    return Rgb{static_cast<double>((hex >> 16) & 0xff) / 255.0,
               static_cast<double>((hex >> 8) & 0xff) / 255.0,
               static_cast<double>(hex & 0xff) / 255.0};
}

/// Tableau 10, the qualitative palette of matplotlib's "tab10".
constexpr std::array<Rgb, kBinColors> kTableau10 = {
    from_hex(0x1f77b4), from_hex(0xff7f0e), from_hex(0x2ca02c), from_hex(0xd62728),
    from_hex(0x9467bd), from_hex(0x8c564b), from_hex(0xe377c2), from_hex(0x7f7f7f),
    from_hex(0xbcbd22), from_hex(0x17becf)};

/// viridis at t = 0, 1/8, ..., 1.
constexpr std::array<Rgb, 9> kViridis = {
    from_hex(0x440154), from_hex(0x472d7b), from_hex(0x3b528b),
    from_hex(0x2c728e), from_hex(0x21918c), from_hex(0x28ae80),
    from_hex(0x5ec962), from_hex(0xaddc30), from_hex(0xfde725)};

double linear(double s) {
    return s > 0.04045 ? std::pow((s + 0.055) / 1.055, 2.4) : s / 12.92;
}

}  // namespace

Rgb bin_color(int bin) {
    const int wrapped = ((bin % kBinColors) + kBinColors) % kBinColors;
    return kTableau10[static_cast<std::size_t>(wrapped)];
}

Rgb height_color(double t) {
    const double clamped = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
    const double x = clamped * static_cast<double>(kViridis.size() - 1);
    const auto k = std::min(static_cast<std::size_t>(x), kViridis.size() - 2);
    const double f = x - static_cast<double>(k);
    const Rgb& a = kViridis[k];
    const Rgb& b = kViridis[k + 1];
    return Rgb{a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

Rgb linear_from_srgb(const Rgb& c) {
    return Rgb{linear(c.r), linear(c.g), linear(c.b)};
}

}  // namespace sgmp::render
