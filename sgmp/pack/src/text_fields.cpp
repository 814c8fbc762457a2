#include "text_fields.hpp"

#include <algorithm>
#include <charconv>

namespace sgmp::detail {

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    split_fields(line, fields);
    return fields;
}

void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    std::size_t pos = 0;
    while (pos < line.size()) {
        while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t')) {
            ++pos;
        }
        const std::size_t start = pos;
        while (pos < line.size() && line[pos] != ' ' && line[pos] != '\t') {
            ++pos;
        }
        if (pos > start) {
            fields.push_back(line.substr(start, pos - start));
        }
    }
}

std::optional<double> parse_double(std::string_view field) {
    if (!field.empty() && field.front() == '+') {
        field.remove_prefix(1);
    }
    double value = 0.0;
    const auto* end = field.data() + field.size();
    const auto result = std::from_chars(field.data(), end, value);
    if (result.ec != std::errc() || result.ptr != end || field.empty()) {
        return std::nullopt;
    }
    return value;
}

std::optional<std::int64_t> parse_integer(std::string_view field) {
    if (!field.empty() && field.front() == '+') {
        field.remove_prefix(1);
    }
    std::int64_t value = 0;
    const auto* end = field.data() + field.size();
    const auto result = std::from_chars(field.data(), end, value);
    if (result.ec != std::errc() || result.ptr != end || field.empty()) {
        return std::nullopt;
    }
    return value;
}

bool is_blank(std::string_view line) {
    return line.find_first_not_of(" \t") == std::string_view::npos;
}

}  // namespace sgmp::detail

#include <cmath>

#include "sgmp/pack/metadata.hpp"

namespace sgmp::detail {

void ParticleValidator::check(const Particle& particle, const LineReader& reader) {
    if (!particle.center.allFinite()) {
        throw reader.error("particle " + std::to_string(particle.id) +
                           " has a coordinate that is not finite");
    }
    if (!std::isfinite(particle.radius) || particle.radius <= 0.0) {
        throw reader.error("particle " + std::to_string(particle.id) + " has radius " +
                           format_number(particle.radius) + "; a radius must be finite and > 0");
    }
    const auto [it, inserted] = line_of_id_.emplace(particle.id, reader.line_number());
    if (!inserted) {
        throw reader.error("id " + std::to_string(particle.id) + " repeats the id of line " +
                           std::to_string(it->second));
    }
}

int decimals_of(std::string_view field) {
    // A loop, not find_first_of("eE"), which searches the set once per character (a memchr
    // call each: a tenth of reading a large pack).
    std::size_t e = 0;
    while (e < field.size() && field[e] != 'e' && field[e] != 'E') {
        ++e;
    }
    if (e == field.size()) {
        e = std::string_view::npos;
    }
    const std::string_view mantissa = field.substr(0, e);
    const std::size_t dot = mantissa.find('.');
    int decimals = dot == std::string_view::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
    if (e != std::string_view::npos) {
        const auto exponent = parse_integer(field.substr(e + 1));
        if (exponent && *exponent > -400 && *exponent < 400) {
            decimals -= static_cast<int>(*exponent);
        }
    }
    return std::max(decimals, 0);
}

}  // namespace sgmp::detail
