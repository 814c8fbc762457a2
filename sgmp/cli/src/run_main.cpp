#include "sgmp/cli/run_main.hpp"

#include "sgmp/cli/help_format.hpp"

#include <algorithm>
#include <iostream>
#include <new>

#include "sgmp/pack/input_error.hpp"

namespace sgmp::cli {
namespace {

/// A message on one line: line breaks (CLI11 writes some) become "; ".
std::string one_line(std::string text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n' || text[i] == '\r') {
            while (!out.empty() && out.back() == ' ') {
                out.pop_back();
            }
            if (i + 1 < text.size() && !out.empty()) {
                out += "; ";
            }
            continue;
        }
        out += text[i];
    }
    return out;
}

int report(std::string_view program, const std::string& message, int status) {
    std::cerr << program << ": " << printable(excerpt(one_line(message), kMaxMessageBytes)) << '\n';
    return status;
}

}  // namespace

std::string option_spelling(std::string_view name, const OptionSpellings& exceptions) {
    if (const auto found = exceptions.find(name); found != exceptions.end()) {
        return found->second;
    }
    std::string option = "--" + std::string(name);
    std::replace(option.begin(), option.end(), '_', '-');
    return option;
}

std::string usage_message(const ParameterError& error, const OptionSpellings& exceptions) {
    const std::string option = option_spelling(error.name(), exceptions);
    return error.value().empty() ? option + ": " + error.rule()
                                 : option + " " + error.value() + ": " + error.rule();
}

std::string failure_message(const std::exception& error) {
    if (dynamic_cast<const std::bad_alloc*>(&error) != nullptr) {
        return "out of memory: the input or the request needs more memory than this process "
               "may use (ulimit -v, the machine)";
    }
    return error.what();
}

std::string out_of_memory_message(const std::string& what) {
    return what +
           ": out of memory: needs more memory than this process may use (ulimit -v, "
           "the machine)";
}

int run_main(std::string_view program, CLI::App& app, const std::function<void()>& parse,
             const std::function<int()>& body, const OptionSpellings& exceptions) {
    wrap_help(app);  // every program's --help within kHelpWidth columns
    try {
        parse();
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help, --version
    } catch (const CLI::ParseError& e) {
        return report(program, std::string(e.what()) + " (see --help)", 2);
    } catch (const ParameterError& e) {
        return report(program, usage_message(e, exceptions), 2);
    } catch (const UsageError& e) {
        return report(program, e.what(), 2);
    } catch (const std::bad_alloc&) {
        return report(program, out_of_memory_message("reading the command line"), 1);
    } catch (const std::exception& e) {  // a --config file that cannot be read: exit 1
        return report(program, failure_message(e), 1);
    }
    try {
        return body();
    } catch (const ParameterError& e) {
        return report(program, usage_message(e, exceptions), 2);
    } catch (const UsageError& e) {
        return report(program, e.what(), 2);
    } catch (const std::exception& e) {  // out of memory outside while_doing: failure_message
        return report(program, failure_message(e), 1);
    }
}

}  // namespace sgmp::cli
