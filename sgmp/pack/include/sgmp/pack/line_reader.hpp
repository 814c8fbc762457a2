#pragma once
/// @file line_reader.hpp
/// The strict line reader every text reader uses (pack files, manifests, thesis tables):
/// lines are counted, so every error can name source:line, and a trailing '\r' is
/// dropped.
#include <cstddef>
#include <istream>
#include <optional>
#include <string>

#include "sgmp/pack/input_error.hpp"

namespace sgmp {

/// The longest line any reader accepts (16 MiB): memory stays bounded on a file of one
/// endless line (/dev/zero, a gzip bomb). The longest real lines are headers of a few kB.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 24;

/// Reads lines while counting them, so every error can name source:line.
class LineReader {
  public:
    LineReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}

    /// Next line without its terminator (a trailing '\r' is dropped); false at the end.
    /// Throws InputError for a line longer than kMaxLineBytes, and on a read error.
    bool next(std::string& line);
    /// Makes `line` the next one returned again (one level of look-back).
    void put_back(std::string line);
    /// True when no line is left to return.
    [[nodiscard]] bool at_end();
    /// True once a call of next() found no line left: whoever called wanted more.
    [[nodiscard]] bool ran_out() const { return ran_out_; }
    /// True when the line most recently returned had no line break after it (the file's
    /// last line, cut off or written without one).
    [[nodiscard]] bool last_line_unterminated() const { return unterminated_; }
    /// Number of the line most recently returned (1-based).
    [[nodiscard]] std::size_t line_number() const { return line_number_; }
    [[nodiscard]] const std::string& source() const { return source_; }

    /// An InputError at the current line.
    [[nodiscard]] InputError error(const std::string& reason) const {
        return InputError(source_, line_number_, reason);
    }

  private:
    bool read_bounded(std::string& line);

    std::istream& in_;
    std::string source_;
    std::size_t line_number_ = 0;
    std::optional<std::string> pushed_;
    bool ran_out_ = false;
    bool unterminated_ = false;
};

}  // namespace sgmp
