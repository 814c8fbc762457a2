#pragma once
/// @file header_entry.hpp
/// What a pack header may hold so that a reader gives it back as it was written.

#include <string>

namespace sgmp {

/// Throws std::invalid_argument unless a header entry reads back as it was written: the
/// key one word (no blank, '=', quote or control byte: "a b" read back as two keys, "x=y"
/// as x with the value "y=1"), the value free of quotes and control bytes (a line break or
/// an ESC made a file the reader refuses). The extended XYZ writer and the Python
/// `sgmp.Pack` check every entry with it.
void check_header_entry(const std::string& key, const std::string& value);

}  // namespace sgmp
