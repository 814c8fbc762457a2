#pragma once
// Private helper of the report writers: the frame of a verdict matrix in Markdown, one
// row per SGMP mode and DEM class under a bold header row per particle count.

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace sgmp::report::detail {

/// "| SGMP mode | DEM class | c₁ | … | agree |" and its separator row.
inline void matrix_header(std::ostringstream& md, const std::vector<std::string>& columns) {
    md << "| SGMP mode | DEM class |";
    for (const std::string& column : columns) {
        md << " " << column << " |";
    }
    md << " agree |\n| --- | --- |";
    for (std::size_t c = 0; c <= columns.size(); ++c) {
        md << " --- |";
    }
    md << "\n";
}

/// The bold "N = n" row that opens a count's block, with `columns` + 1 empty cells.
inline void count_header_row(std::ostringstream& md, std::size_t count, std::size_t columns) {
    md << "| **N = " << count << "** | |";
    for (std::size_t c = 0; c <= columns; ++c) {
        md << " |";
    }
    md << "\n";
}

/// The last cell: "k of K" agree, or "·" when nothing was judged.
inline std::string agree_cell(std::size_t agree, std::size_t judged) {
    return judged > 0 ? std::to_string(agree) + " of " + std::to_string(judged) : std::string("·");
}

}  // namespace sgmp::report::detail
