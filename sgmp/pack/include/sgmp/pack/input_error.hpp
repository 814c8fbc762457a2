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

class InputError : public std::runtime_error {
  public:
    /// `line` is 1-based; 0 means the error concerns the file as a whole.
    InputError(const std::string& source, std::size_t line, const std::string& reason);

    [[nodiscard]] const std::string& source() const { return source_; }
    [[nodiscard]] std::size_t line() const { return line_; }

  private:
    std::string source_;
    std::size_t line_;
};

}  // namespace sgmp
