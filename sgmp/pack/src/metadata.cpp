#include "sgmp/pack/metadata.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>

namespace sgmp {

std::string format_number(double value) {
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return {buffer.data(), result.ptr};
}

void Metadata::set(std::string_view key, std::string value) {
    const auto found = std::find_if(entries_.begin(), entries_.end(),
                                    [&](const Entry& entry) { return entry.first == key; });
    if (found != entries_.end()) {
        found->second = std::move(value);
    } else {
        entries_.emplace_back(std::string(key), std::move(value));
    }
}

void Metadata::erase(std::string_view key) {
    std::erase_if(entries_, [&](const Entry& entry) { return entry.first == key; });
}

void Metadata::set_number(std::string_view key, double value) {
    set(key, format_number(value));
}

void Metadata::set_integer(std::string_view key, long long value) {
    set(key, std::to_string(value));
}

std::optional<std::string> Metadata::get(std::string_view key) const {
    const auto found = std::find_if(entries_.begin(), entries_.end(),
                                    [&](const Entry& entry) { return entry.first == key; });
    if (found == entries_.end()) {
        return std::nullopt;
    }
    return found->second;
}

std::optional<double> Metadata::get_number(std::string_view key) const {
    const auto text = get(key);
    if (!text) {
        return std::nullopt;
    }
    double value = 0.0;
    const auto* end = text->data() + text->size();
    const auto result = std::from_chars(text->data(), end, value);
    if (result.ec != std::errc() || result.ptr != end) {
        throw std::invalid_argument("metadata key '" + std::string(key) + "' has value '" + *text +
                                    "', which is not a number");
    }
    return value;
}

}  // namespace sgmp
