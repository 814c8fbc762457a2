// Markdown rendered as HTML by md4c (GitHub dialect: pipe tables, strikethrough, autolinks).
#include <md4c-html.h>

#include <stdexcept>

#include "sgmp/report/report_render.hpp"

namespace sgmp::report {
namespace {

void append(const MD_CHAR* text, MD_SIZE size, void* out) {
    static_cast<std::string*>(out)->append(text, size);
}

}  // namespace

std::string markdown_to_html(const std::string& markdown) {
    std::string html;
    const int status = md_html(markdown.data(), static_cast<MD_SIZE>(markdown.size()), append,
                               &html, MD_DIALECT_GITHUB | MD_FLAG_NOHTML, 0);
    if (status != 0) {
        throw std::runtime_error("markdown rendering failed");
    }
    return html;
}

}  // namespace sgmp::report
