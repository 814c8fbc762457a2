#include "sgmp/pack/metadata.hpp"

#include "sgmp/pack/header_entry.hpp"
#include "sgmp/pack/input_error.hpp"

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

namespace {

bool is_control(unsigned char c) {
    return c < 0x20 || c == 0x7f;
}

}  // namespace

void check_header_entry(const std::string& key, const std::string& value) {
    // "a b" read back as two keys and "x=y" as x with the value "y=1"; a line break or an
    // ESC made a file the reader refuses.
    const bool bad_key =
        key.empty() || std::any_of(key.begin(), key.end(), [](char c) {
            return is_control(static_cast<unsigned char>(c)) || c == ' ' || c == '=' || c == '"';
        });
    if (bad_key) {
        throw std::invalid_argument("header key '" + printable(key) +
                                    "' must be one word: no blank, '=', quote or control "
                                    "character");
    }
    if (value.find('"') != std::string::npos || std::any_of(value.begin(), value.end(), [](char c) {
            return is_control(static_cast<unsigned char>(c));
        })) {
        throw std::invalid_argument("header value of '" + key + "' ('" + printable(value) +
                                    "') contains a quote, line break or control character");
    }
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
