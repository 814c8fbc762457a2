#include "sgmp/report/contact_windows.hpp"

#include <algorithm>

namespace sgmp::report {

namespace {
/// The window around a contact range: DEM overlaps reach about 1 % of σ below it (2 % with
/// rounding to a bin), and the peak's shoulder 10 % above, as the equal spheres' 1.1·d.
constexpr double kBelow = 0.98;
constexpr double kAbove = 1.1;
}  // namespace

std::vector<ContactRange> contact_ranges(const std::vector<double>& species_diameters,
                                         double smallest, double largest) {
    std::vector<ContactRange> ranges;
    if (species_diameters.size() >= 2) {
        for (std::size_t i = 0; i < species_diameters.size(); ++i) {
            for (std::size_t j = i; j < species_diameters.size(); ++j) {
                const double sigma = 0.5 * (species_diameters[i] + species_diameters[j]);
                ranges.push_back({sigma, sigma});
            }
        }
    } else if (largest > smallest) {
        ranges.push_back({smallest, largest});
    }
    return ranges;
}

bool outside_contact_windows(double r_lo, double r_hi, const std::vector<ContactRange>& ranges) {
    return std::none_of(ranges.begin(), ranges.end(), [&](const ContactRange& c) {
        return r_hi > kBelow * c.lo && r_lo < kAbove * c.hi;
    });
}

}  // namespace sgmp::report
