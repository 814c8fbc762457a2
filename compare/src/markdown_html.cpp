// The small Markdown subset of report lead sections rendered as HTML.
#include <sstream>
#include <vector>

#include "html_text.hpp"
#include "sgmp/compare/report_render.hpp"

namespace sgmp::compare {

using detail::html_escape;

namespace {

/// **bold** and `code` spans of one escaped line.
std::string inline_markup(const std::string& escaped) {
    std::string out;
    bool bold = false;
    bool code = false;
    for (std::size_t i = 0; i < escaped.size(); ++i) {
        if (escaped.compare(i, 2, "**") == 0 && !code) {
            out += bold ? "</b>" : "<b>";
            bold = !bold;
            ++i;
        } else if (escaped[i] == '`') {
            out += code ? "</code>" : "<code>";
            code = !code;
        } else {
            out += escaped[i];
        }
    }
    return out;
}

std::vector<std::string> table_cells(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = line.find('|') + 1;
    while (start < line.size()) {
        const std::size_t bar = line.find('|', start);
        if (bar == std::string::npos) {
            break;
        }
        std::string cell = line.substr(start, bar - start);
        const auto first = cell.find_first_not_of(' ');
        const auto last = cell.find_last_not_of(' ');
        cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
        start = bar + 1;
    }
    return cells;
}

}  // namespace

std::string markdown_to_html(const std::string& markdown) {
    std::ostringstream html;
    std::istringstream in(markdown);
    std::string line;
    enum class Block { None, List, Table } block = Block::None;
    bool header_row = false;
    const auto close = [&] {
        html << (block == Block::List ? "</ul>\n" : block == Block::Table ? "</table>\n" : "");
        block = Block::None;
    };
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) {
            close();
            html << "<h2>" << inline_markup(html_escape(line.substr(3))) << "</h2>\n";
        } else if (line.rfind("- ", 0) == 0) {
            if (block != Block::List) {
                close();
                html << "<ul>\n";
                block = Block::List;
            }
            html << "<li>" << inline_markup(html_escape(line.substr(2))) << "</li>\n";
        } else if (line.rfind("|", 0) == 0) {
            if (block != Block::Table) {
                close();
                html << "<table>\n";
                block = Block::Table;
                header_row = true;
            }
            const auto cells = table_cells(line);
            if (!cells.empty() && cells[0].find_first_not_of("-: ") == std::string::npos) {
                continue;  // the alignment row
            }
            html << "<tr>";
            for (const auto& cell : cells) {
                const char* tag = header_row ? "th" : "td";
                const bool differs = cell == "DIFFER";
                html << "<" << tag << (differs ? " class=\"DISAGREE\"" : "") << ">"
                     << inline_markup(html_escape(cell)) << "</" << tag << ">";
            }
            html << "</tr>\n";
            header_row = false;
        } else if (line.find_first_not_of(' ') == std::string::npos) {
            close();
        } else {
            close();
            html << "<p>" << inline_markup(html_escape(line)) << "</p>\n";
        }
    }
    close();
    return html.str();
}

}  // namespace sgmp::compare
