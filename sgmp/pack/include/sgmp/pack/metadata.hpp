#pragma once
/// @file metadata.hpp
/// Provenance of a pack: ordered key=value pairs (tool, version, parameters, seed).

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sgmp {

/// Ordered key/value record. Keys keep the order in which they were first set, so the
/// same run writes the same header bytes. Keys are identifiers ([A-Za-z_][A-Za-z0-9_-]*).
class Metadata {
  public:
    using Entry = std::pair<std::string, std::string>;

    /// Sets `key` to `value`, keeping the key's position if it already exists.
    void set(std::string_view key, std::string value);
    /// Numbers are written in the shortest form that reads back to the same double.
    void set_number(std::string_view key, double value);
    void set_integer(std::string_view key, long long value);
    /// Removes `key` (nothing when absent).
    void erase(std::string_view key);

    [[nodiscard]] std::optional<std::string> get(std::string_view key) const;
    /// The value parsed as a number; nullopt when absent. Throws std::invalid_argument
    /// naming the key and value when present but not a number.
    [[nodiscard]] std::optional<double> get_number(std::string_view key) const;
    [[nodiscard]] bool contains(std::string_view key) const { return get(key).has_value(); }
    [[nodiscard]] const std::vector<Entry>& entries() const { return entries_; }

  private:
    std::vector<Entry> entries_;
};

/// Shortest decimal text that parses back to exactly `value` (std::to_chars).
std::string format_number(double value);

}  // namespace sgmp
