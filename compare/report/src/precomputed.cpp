#include "sgmp/report/precomputed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "precomputed_text.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/metrics/summary_columns.hpp"
#include "sgmp/pack/csv_fields.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

using detail::count_of;
using detail::kUnknown;
using detail::lines_of;
using metrics::coordination_tolerance_names;
using metrics::kSchemaVersion;
using metrics::summary_column_of;
using metrics::summary_columns;
using metrics::SummaryColumn;

namespace {

/// Columns `wanted` of a CSV in the testbed layout (header, `#` lines, rows).
std::vector<std::vector<double>> columns(std::string_view text, const std::string& source,
                                         const std::vector<std::string>& wanted) {
    const auto lines = lines_of(text);
    if (lines.empty()) {
        throw InputError(source, 0, "is empty");
    }
    const auto header = split_csv_line(lines.front());
    std::vector<std::size_t> at;
    for (const auto& name : wanted) {
        const auto found = std::find(header.begin(), header.end(), name);
        if (found == header.end()) {
            throw InputError(source, 1, "has no column '" + name + "'");
        }
        at.push_back(static_cast<std::size_t>(found - header.begin()));
    }
    std::vector<std::vector<double>> out(wanted.size());
    for (std::size_t n = 1; n < lines.size(); ++n) {
        if (lines[n].empty() || lines[n].front() == '#') {
            continue;
        }
        const auto fields = split_csv_line(lines[n]);
        for (std::size_t c = 0; c < at.size(); ++c) {
            double value = 0.0;
            const std::string& f = at[c] < fields.size() ? fields[at[c]] : std::string();
            const auto r = std::from_chars(f.data(), f.data() + f.size(), value);
            if (f.empty() || r.ec != std::errc() || r.ptr != f.data() + f.size()) {
                throw InputError(source, n + 1, "'" + wanted[c] + "' is not a number");
            }
            out[c].push_back(value);
        }
    }
    return out;
}

double number_at(const nlohmann::ordered_json& j, const std::string& key,
                 const std::string& source) {
    if (!j.contains(key) || !j[key].is_number()) {
        throw InputError(source, 0, "has no number '" + key + "'");
    }
    return j[key].get<double>();
}

/// The array of numbers at j[key][name], named in the error when it is missing or is not
/// one (not nlohmann's internal text).
std::vector<double> numbers_at(const nlohmann::ordered_json& j, const std::string& key,
                               const std::string& name, const std::string& source) {
    const std::string what = "'" + key + "' entry '" + name + "'";
    if (!j.contains(key) || !j[key].is_object() || !j[key].contains(name)) {
        throw InputError(source, 0, "has no " + what);
    }
    const auto& array = j[key][name];
    if (!array.is_array() ||
        !std::all_of(array.begin(), array.end(), [](const auto& v) { return v.is_number(); })) {
        throw InputError(
            source, 0,
            what + " must be an array of numbers, not " + std::string(array.type_name()));
    }
    return array.get<std::vector<double>>();
}

/// The object at j[key], named in the error when it is missing.
const nlohmann::ordered_json& object_at(const nlohmann::ordered_json& j, const std::string& key,
                                        const std::string& source) {
    if (!j.contains(key) || !j[key].is_object()) {
        throw InputError(source, 0, "has no object '" + key + "'");
    }
    return j[key];
}

/// "'KEY' must be TYPE, not ACTUAL": a value of the wrong JSON type, named in one line
/// (nlohmann's own text, "[json.exception.type_error.302] …", names neither).
[[noreturn]] void wrong_type(const std::string& source, const std::string& key,
                             const std::string& expected, const nlohmann::ordered_json& value) {
    throw InputError(source, 0, "'" + key + "' must be " + expected + ", not " + value.type_name());
}

/// The object at j[key], or an empty one when the key is absent.
nlohmann::ordered_json optional_object(const nlohmann::ordered_json& j, const std::string& key,
                                       const std::string& name, const std::string& source) {
    if (!j.contains(key)) {
        return nlohmann::ordered_json::object();
    }
    if (!j[key].is_object()) {
        wrong_type(source, name, "an object", j[key]);
    }
    return j[key];
}

/// The string at j[key], or `fallback` when the key is absent.
std::string optional_string(const nlohmann::ordered_json& j, const std::string& key,
                            const std::string& name, const std::string& fallback,
                            const std::string& source) {
    if (!j.contains(key)) {
        return fallback;
    }
    if (!j[key].is_string()) {
        wrong_type(source, name, "a string", j[key]);
    }
    return j[key].get<std::string>();
}

/// Refuses all but a metrics object of this schema_version. The version is read as a
/// number and checked to be whole and in range before it is compared (a float such as
/// 218356777100.571 converted to int was undefined behaviour, a fuzz finding).
void check_schema_version(const nlohmann::ordered_json& j, const std::string& source) {
    const std::string expected = "is not a metrics file of schema_version " +
                                 std::to_string(kSchemaVersion) + " (sgmp-compare measure)";
    if (!j.is_object() || !j.contains("schema_version")) {
        throw InputError(source, 0, expected);
    }
    const auto& version = j["schema_version"];
    if (!version.is_number()) {
        wrong_type(source, "schema_version", "a whole number", version);
    }
    const double value = version.get<double>();
    constexpr double kLargest = 1e6;  // far above any schema version
    if (!(value >= 0.0 && value <= kLargest) || value != std::floor(value) ||
        static_cast<int>(value) != kSchemaVersion) {
        throw InputError(source, 0, expected + "; its schema_version is " + version.dump());
    }
}

/// The contact ranges (contact_windows.hpp) of a metrics.json: its species' diameters
/// over d, else its radius span.
std::vector<ContactRange> contact_ranges_of(const nlohmann::ordered_json& j, double diameter,
                                            const std::string& source) {
    std::vector<double> species_diameters;
    if (j.contains("species") && j.at("species").is_object()) {
        for (const auto& one : j.at("species").value("species", nlohmann::ordered_json::array())) {
            species_diameters.push_back(number_at(one, "diameter_over_d", source));
        }
    }
    const double smallest = j.contains("radius_min") ? number_at(j, "radius_min", source) : 0.0;
    const double largest = j.contains("radius_max") ? number_at(j, "radius_max", source) : 0.0;
    return contact_ranges(species_diameters, 2.0 * smallest / diameter, 2.0 * largest / diameter);
}

/// "'KEY' is VALUE: RULE", one line naming the file, the key and the rule it breaks.
[[noreturn]] void out_of_range(const std::string& source, const std::string& key, double value,
                               const std::string& rule) {
    throw InputError(source, 0, "'" + key + "' is " + format_number(value) + ": " + rule);
}

/// A whole number of spheres in [0, most] at j[key], when the key is there.
void check_sphere_count(const nlohmann::ordered_json& j, const std::string& key,
                        const std::string& name, double most, const std::string& source) {
    if (!j.contains(key)) {
        return;
    }
    const double value = number_at(j, key, source);
    if (!(value >= 0.0 && value <= most) || value != std::floor(value)) {
        out_of_range(
            source, name, value,
            "must be a whole number of spheres from 0 to the count, " + format_number(most));
    }
}

/// The values of a metrics file checked against their physical range and against each
/// other, before anything is judged (reliability finding 10: a diameter of 0 or 1e300, a
/// count of 61 for a pack of 60, were taken): the mean diameter finite and > 0 and between
/// the smallest and largest sphere; the counts of origins, species and the g(r) space's
/// spheres consistent with `count`; each P(Z) a histogram of the origins (every bin a
/// whole number of them). φ, φ(y), Z and g(r) are check_physical's.
void check_measure_values(const nlohmann::ordered_json& j, const PackSummary& s,
                          const std::string& source) {
    const double count = static_cast<double>(s.count);
    if (!std::isfinite(s.diameter) || s.diameter <= 0.0) {
        out_of_range(source, "diameter", s.diameter, "the mean diameter must be finite and > 0");
    }
    const double smallest = j.contains("radius_min") ? number_at(j, "radius_min", source) : NAN;
    const double largest = j.contains("radius_max") ? number_at(j, "radius_max", source) : NAN;
    for (const auto& [key, radius] : {std::pair{"radius_min", smallest}, {"radius_max", largest}}) {
        if (j.contains(key) && !(std::isfinite(radius) && radius > 0.0)) {
            out_of_range(source, key, radius, "a radius must be finite and > 0");
        }
    }
    const double half = 0.5 * s.diameter;
    constexpr double kRounding = 1e-9;  // relative: d is a mean of the radii, in doubles
    if ((std::isfinite(smallest) && half < smallest * (1.0 - kRounding)) ||
        (std::isfinite(largest) && half > largest * (1.0 + kRounding))) {
        out_of_range(source, "diameter", s.diameter,
                     "half the mean diameter must lie between radius_min and radius_max");
    }
    check_sphere_count(j, "origins", "origins", count, source);
    if (j.contains("g_r_detail") && j["g_r_detail"].is_object()) {
        const auto& rdf = j["g_r_detail"];
        check_sphere_count(rdf, "origins", "g_r_detail.origins", count, source);
        // N / volume of the g(r) space (local_structure.cpp), when that space lies inside
        // the walls: with periodic sides it is widened and its N counts the images too.
        if (rdf.contains("space_density") && rdf.contains("space") && j.contains("container") &&
            j["container"].is_string()) {
            const double density = number_at(rdf, "space_density", source);
            const auto& space = rdf["space"];
            std::optional<Container> walls;
            try {
                walls = Container::parse(j["container"].get<std::string>());
            } catch (const std::invalid_argument&) {
                throw InputError(source, 0,
                                 "'container' is '" + j["container"].get<std::string>() +
                                     "': must be five finite numbers x_min x_max z_min z_max "
                                     "floor");
            }
            if (space.is_object()) {
                const auto lo = numbers_at(rdf, "space", "lo", source);
                const auto hi = numbers_at(rdf, "space", "hi", source);
                if (lo.size() != 3 || hi.size() != 3) {
                    throw InputError(source, 0,
                                     "'g_r_detail.space' must hold lo and hi of 3 numbers");
                }
                const double volume = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
                const bool inside = lo[0] >= walls->x_min && hi[0] <= walls->x_max &&
                                    lo[2] >= walls->z_min && hi[2] <= walls->z_max;
                const double spheres = density * volume;
                if (inside && std::isfinite(spheres) &&
                    std::abs(spheres - count) > 1e-6 * count + 1e-6) {
                    out_of_range(source, "count", count,
                                 "g_r_detail.space_density times the volume of its space holds " +
                                     format_number(spheres) +
                                     " spheres; the count must be the pack's");
                }
            }
        }
    }
    if (j.contains("species") && j["species"].is_object() && j["species"].contains("species") &&
        j["species"]["species"].is_array() && !j["species"]["species"].empty()) {
        double sum = 0.0;
        for (const auto& one : j["species"]["species"]) {
            check_sphere_count(one, "count", "species.count", count, source);
            sum += one.contains("count") ? number_at(one, "count", source) : 0.0;
        }
        if (sum != count) {
            out_of_range(source, "count", count,
                         "the species' counts add up to " + format_number(sum) +
                             "; the count must be their sum");
        }
    }
    const double origins = j.contains("origins") ? number_at(j, "origins", source) : NAN;
    const auto& names = coordination_tolerance_names();
    for (std::size_t t = 0; t < s.p_z.size() && std::isfinite(origins) && origins > 0.0; ++t) {
        for (const double q : s.p_z[t]) {
            const double spheres = q * origins;
            if (std::abs(spheres - std::round(spheres)) > 1e-6 * origins) {
                out_of_range(source, "p_z." + names.at(t), q,
                             "P(Z) is a histogram of the " + format_number(origins) +
                                 " origins: each bin must be a whole number of them over the "
                                 "origins");
            }
        }
    }
}

}  // namespace

bool is_metrics_json(std::string_view path) {
    constexpr std::string_view suffix = ".metrics.json";
    return path.size() > suffix.size() && path.substr(path.size() - suffix.size()) == suffix;
}

std::string sibling_csv(const std::string& metrics_path, const std::string& kind) {
    return metrics_path.substr(0, metrics_path.size() - std::string_view(".metrics.json").size()) +
           "." + kind + ".csv";
}

PackSummary summary_from_measure(const std::string& source, const nlohmann::ordered_json& j,
                                 std::string_view g_r_csv, std::string_view phi_y_csv,
                                 const nlohmann::ordered_json& parameters) {
    check_schema_version(j, source);
    const nlohmann::ordered_json prov = optional_object(j, "provenance", "provenance", source);
    const nlohmann::ordered_json recorded = prov.value("parameters", nlohmann::ordered_json());
    if (parameters != recorded) {
        throw InputError(source, 0,
                         "was measured with other parameters (" + recorded.dump() +
                             ") than this run's (" + parameters.dump() + ")");
    }
    PackSummary s;
    s.source = optional_string(prov, "input", "provenance.input", source, source);
    const nlohmann::ordered_json metadata =
        optional_object(prov, "input_metadata", "provenance.input_metadata", source);
    for (const auto& [key, value] : metadata.items()) {
        s.provenance.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
    }
    s.count = count_of(number_at(j, "count", source), source, 0);
    s.diameter = number_at(j, "diameter", source);
    s.contact_ranges = contact_ranges_of(j, s.diameter, source);
    for (const auto& rule : metric_rules()) {
        if (rule.kind == MetricKind::Scalar) {
            s.scalars.push_back(j.contains(rule.name) ? number_at(j, rule.name, source) : 0.0);
        }
    }
    const auto& names = coordination_tolerance_names();
    for (const auto& name : names) {
        const std::size_t t = s.z_mean.size();
        s.z_mean.push_back(number_at(j, metrics::coordination_metric(t).name, source));
        s.p_z.push_back(numbers_at(j, "p_z", name, source));
    }
    s.gr_bin_width = number_at(object_at(j, "g_r_detail", source), "bin_width_over_d", source);
    const std::string g_r_source =
        sibling_csv(source, metrics::metric_with(metrics::MetricRole::PairCorrelation).name);
    auto gr = columns(g_r_csv, g_r_source, {"r_over_d", "g"});
    s.gr_r = std::move(gr[0]);
    s.gr = std::move(gr[1]);
    auto phi = columns(phi_y_csv, sibling_csv(source, "phi_y"), {"y_mid", "phi"});
    s.phi_y_mid = std::move(phi[0]);
    s.phi_y = std::move(phi[1]);
    check_measure_values(j, s, source);
    try {
        check_physical(s);  // the rule every judged pack keeps, named against this file
    } catch (const std::invalid_argument& error) {
        throw InputError(source, 0, error.what());
    }
    return s;
}

namespace detail {

std::vector<std::string_view> lines_of(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

/// A recorded particle count: a whole number in [1, 2⁵³] (beyond, a double no longer holds
/// every whole number, and the cast to size_t would be undefined).
std::size_t count_of(double value, const std::string& source, std::size_t line) {
    constexpr double kLargest = 9007199254740992.0;  // 2⁵³
    if (!(value >= 1.0 && value <= kLargest) || value != std::floor(value)) {
        throw InputError(source, line,
                         "count " + format_number(value) +
                             " must be a whole number of particles from 1 to 2^53");
    }
    return static_cast<std::size_t>(value);
}

}  // namespace detail

}  // namespace sgmp::report
