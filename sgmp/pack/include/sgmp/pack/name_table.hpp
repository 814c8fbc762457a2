#pragma once
/// @file name_table.hpp
/// One table of names per enum: parse, to_string and the "one of …" text of an option all
/// come from it, so a choice added to the enum appears everywhere at once (the command
/// line, the Python module, sweeps, pack headers).
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace sgmp {

template <class Enum, std::size_t N>
struct NameTable {
    std::array<std::pair<Enum, std::string_view>, N> entries;

    [[nodiscard]] constexpr std::optional<Enum> parse(std::string_view text) const {
        for (const auto& [value, name] : entries) {
            if (name == text) {
                return value;
            }
        }
        return std::nullopt;
    }
    [[nodiscard]] constexpr std::string_view name(Enum value) const {
        for (const auto& [v, name] : entries) {
            if (v == value) {
                return name;
            }
        }
        return entries.front().second;
    }
    /// "a, b, c": the names in table order.
    [[nodiscard]] std::string choices() const {
        std::string text;
        for (const auto& [value, name] : entries) {
            text += (text.empty() ? "" : ", ") + std::string(name);
        }
        return text;
    }
};

}  // namespace sgmp
