#include "sgmp/cli/help_format.hpp"

#include <memory>
#include <sstream>

namespace sgmp::cli {

namespace {

/// CLI11's formatter with its descriptions wrapped under the description column.
class WrappingFormatter : public CLI::Formatter {
  public:
    explicit WrappingFormatter(std::size_t width) : width_(width) {}

    std::string make_option_desc(const CLI::Option* option) const override {
        return wrap_words(CLI::Formatter::make_option_desc(option), text_width());
    }

    std::string make_subcommand(const CLI::App* sub) const override {
        std::stringstream out;
        CLI::detail::format_help(out, sub->get_display_name(true),
                                 wrap_words(sub->get_description(), text_width()),
                                 get_column_width());
        return out.str();
    }

    std::string make_description(const CLI::App* app) const override {
        return wrap_words(CLI::Formatter::make_description(app), width_);
    }

  private:
    /// Columns left for a description beside the option column (two for its indent).
    [[nodiscard]] std::size_t text_width() const {
        const std::size_t used = get_column_width() + 2;
        return width_ > used + 20 ? width_ - used : 20;
    }

    std::size_t width_;
};

void give_formatter(CLI::App& app, const std::shared_ptr<CLI::FormatterBase>& formatter) {
    app.formatter(formatter);
    for (CLI::App* sub : app.get_subcommands({})) {
        give_formatter(*sub, formatter);
    }
}

}  // namespace

std::string wrap_words(const std::string& text, std::size_t width) {
    std::string out;
    std::size_t line = 0;  // bytes on the current output line
    std::size_t at = 0;
    while (at < text.size()) {
        if (text[at] == '\n') {
            out += '\n';
            line = 0;
            ++at;
            continue;
        }
        const std::size_t end = text.find_first_of(" \n", at);
        const std::size_t stop = end == std::string::npos ? text.size() : end;
        const std::string word = text.substr(at, stop - at);
        if (line > 0 && line + 1 + word.size() > width) {
            out += '\n';
            line = 0;
        } else if (line > 0) {
            out += ' ';
            ++line;
        }
        out += word;
        line += word.size();
        at = stop;
        while (at < text.size() && text[at] == ' ') {
            ++at;  // runs of spaces collapse into the one break or blank
        }
    }
    return out;
}

void wrap_help(CLI::App& app, std::size_t width) {
    give_formatter(app, std::make_shared<WrappingFormatter>(width));
}

}  // namespace sgmp::cli
