#include "text_fields.hpp"

#include <algorithm>
#include <bit>
#include <charconv>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sgmp::detail {

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    split_fields(line, fields);
    return fields;
}

// Fields are found from a mask of the line's field characters (not blank, not tab), 16
// characters at a time where SSE2 is there: a field starts where the mask rises and ends
// where it falls. `inside` carries the state across blocks.
void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    const char* const text = line.data();
    const std::size_t size = line.size();
    std::size_t pos = 0;
    std::size_t start = 0;
    bool inside = false;
#if defined(__SSE2__)
    const __m128i blank = _mm_set1_epi8(' ');
    const __m128i tab = _mm_set1_epi8('\t');
    for (; pos + 16 <= size; pos += 16) {
        const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(text + pos));
        const auto separators = static_cast<unsigned>(_mm_movemask_epi8(
            _mm_or_si128(_mm_cmpeq_epi8(block, blank), _mm_cmpeq_epi8(block, tab))));
        const unsigned field = ~separators & 0xFFFFu;
        // Bit i is set where character i differs from character i − 1 (field or not).
        unsigned changes = (field ^ ((field << 1) | (inside ? 1u : 0u))) & 0xFFFFu;
        while (changes != 0) {
            const std::size_t at = pos + static_cast<std::size_t>(std::countr_zero(changes));
            if (inside) {
                fields.emplace_back(text + start, at - start);
            } else {
                start = at;
            }
            inside = !inside;
            changes &= changes - 1;
        }
    }
#endif
    for (; pos < size; ++pos) {
        const bool field = text[pos] != ' ' && text[pos] != '\t';
        if (field && !inside) {
            start = pos;
        } else if (!field && inside) {
            fields.emplace_back(text + start, pos - start);
        }
        inside = field;
    }
    if (inside) {
        fields.emplace_back(text + start, size - start);
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

std::optional<int> parse_bin(std::string_view field) {
    const auto value = parse_integer(field);
    if (!value || *value < 0 || *value > kMaxBin) {
        return std::nullopt;
    }
    return static_cast<int>(*value);
}

std::string bin_error(std::string_view field) {
    return "bin '" + std::string(field) + "' is not an integer in [0, " + std::to_string(kMaxBin) +
           "]";
}

void HeaderKeys::add(const std::string& key, const std::string& value, const LineReader& reader) {
    if (seen_.size() >= kMaxHeaderKeys) {
        throw reader.error("more than " + std::to_string(kMaxHeaderKeys) +
                           " header keys (the readers' limit)");
    }
    if (seen_.contains(key)) {
        throw reader.error("header key '" + key + "' appears twice");
    }
    const auto control = [](const std::string& text) {
        return std::any_of(text.begin(), text.end(), [](char c) {
            const auto byte = static_cast<unsigned char>(c);
            return (byte < 0x20 && byte != '\t') || byte == 0x7f;
        });
    };
    if (control(key) || control(value)) {  // would reach terminals and copies raw
        throw reader.error("header entry '" + key + "=" + value + "' holds a control character");
    }
    if (!is_utf8(key) || !is_utf8(value)) {  // would break the JSON outputs after a whole run
        throw reader.error("header entry '" + key + "=" + value +
                           "' is not UTF-8 (a Latin-1 byte?): header text must be UTF-8");
    }
    seen_.insert(key);
}

bool is_blank(std::string_view line) {
    return line.find_first_not_of(" \t") == std::string_view::npos;
}

void check_one_size_column(bool radius, bool diameter, const std::string& columns,
                           const LineReader& reader) {
    if (radius && diameter) {
        throw reader.error(columns +
                           " holds both 'radius' and 'diameter': give one (which would count is "
                           "not clear)");
    }
}

}  // namespace sgmp::detail

#include <cmath>

#include "sgmp/pack/metadata.hpp"

namespace sgmp::detail {

void check_particle_values(const Particle& particle, const std::string& source, std::size_t line) {
    if (!particle.center.allFinite()) {
        throw InputError(
            source, line,
            "particle " + std::to_string(particle.id) + " has a coordinate that is not finite");
    }
    if (!std::isfinite(particle.radius) || particle.radius <= 0.0) {
        throw InputError(source, line,
                         "particle " + std::to_string(particle.id) + " has radius " +
                             format_number(particle.radius) + "; a radius must be finite and > 0");
    }
}

void ParticleValidator::check(const Particle& particle, const LineReader& reader) {
    check_particle_values(particle, reader.source(), reader.line_number());
    check_id(particle.id, reader.source(), reader.line_number());
}

void ParticleValidator::check_id(std::int64_t id, const std::string& source, std::size_t line) {
    // The table grows to hold an id when that keeps it within a few entries per id seen.
    constexpr std::size_t kSlack = 1 << 16;
    const bool dense = id >= 0 && static_cast<std::uint64_t>(id) < 4 * (seen_ + kSlack);
    std::size_t earlier = 0;
    if (dense) {
        const auto slot = static_cast<std::size_t>(id);
        if (slot >= dense_line_.size()) {
            dense_line_.resize(std::max(slot + 1, 2 * dense_line_.size()), 0);
        }
        earlier = dense_line_[slot];
        if (earlier == 0 && !sparse_line_.empty()) {
            // An id first met outside the table's range stays in the map.
            const auto it = sparse_line_.find(id);
            earlier = it == sparse_line_.end() ? 0 : it->second;
        }
        if (earlier == 0) {
            dense_line_[slot] = line;
        }
    } else {
        const auto [it, inserted] = sparse_line_.emplace(id, line);
        earlier = inserted ? 0 : it->second;
    }
    if (earlier != 0) {
        throw InputError(
            source, line,
            "id " + std::to_string(id) + " repeats the id of line " + std::to_string(earlier));
    }
    ++seen_;
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
