#pragma once
/// @file input_error.hpp
/// The error every reader throws: one line, "file:line: reason", with non-printable bytes
/// escaped.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sgmp {

/// `text` safe to print on a terminal: control characters and bytes outside printable
/// ASCII become \xNN (tab stays a tab), so a binary file's bytes are never echoed raw.
std::string printable(std::string_view text);

/// `text` when at most `max` bytes long; else its first and last bytes, about `max` in all,
/// around " ... [N bytes left out] ... ": an error quoting a line of 16 MiB stays one
/// short line, and keeps the rule that ends it.
std::string excerpt(std::string_view text, std::size_t max);

/// The most bytes of a reason an InputError keeps (excerpt); the longest real reasons are
/// a quoted header line of a few hundred bytes.
inline constexpr std::size_t kMaxReasonBytes = 600;

/// True when `text` is well-formed UTF-8 (no stray continuation byte, no overlong form, no
/// surrogate, nothing beyond U+10FFFF). Text that reaches a JSON output must be: a Latin-1
/// byte in a header value or a group name made the JSON writer fail after a whole run.
bool is_utf8(std::string_view text);

class InputError : public std::runtime_error {
  public:
    /// `line` is 1-based; 0 means the error concerns the file as a whole. A reason longer
    /// than kMaxReasonBytes is cut to its excerpt.
    InputError(const std::string& source, std::size_t line, const std::string& reason);

    [[nodiscard]] const std::string& source() const { return source_; }
    [[nodiscard]] std::size_t line() const { return line_; }

  private:
    std::string source_;
    std::size_t line_;
};

}  // namespace sgmp
