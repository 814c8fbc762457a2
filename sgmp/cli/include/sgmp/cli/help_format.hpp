#pragma once
/// @file help_format.hpp
/// `--help` within a terminal's width: descriptions of options and subcommands are wrapped
/// at word boundaries so that no line passes `width` columns (CLI11 2.1 prints each on one
/// line, up to about 250 columns), continued under the description column.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

namespace sgmp::cli {

/// The widest help line, in columns (bytes of ASCII; a UTF-8 sign counts once per byte, so
/// lines with them are shorter on screen).
inline constexpr std::size_t kHelpWidth = 100;

/// `text` broken at spaces into lines of at most `width` bytes (a word longer than that
/// stays whole); existing line breaks are kept.
std::string wrap_words(const std::string& text, std::size_t width);

/// Gives `app` and every subcommand under it a formatter that wraps to `width` columns.
void wrap_help(CLI::App& app, std::size_t width = kHelpWidth);

}  // namespace sgmp::cli
