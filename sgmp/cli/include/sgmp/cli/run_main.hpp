#pragma once
/// @file run_main.hpp
/// The one error contract of the three command lines (`sgmp`, `sgmp-reference`,
/// `sgmp-compare`): every message is one line prefixed with the program's name, and
///
/// | exit | when |
/// | --- | --- |
/// | 0 | success (also `--help`, `--version`) |
/// | 1 | a bad input file or a runtime failure (any other exception) |
/// | 2 | a usage error: CLI11's parse errors, UsageError, ParameterError |
/// | 130 | interrupted (sgmp/pack/interrupt.hpp) |
///
/// A ParameterError names the parameter as the libraries spell it (`phi_target`); a
/// program shows it as its option (`--phi-target`), through `option_spelling` and the
/// program's own exceptions to that rule.
#include <cstddef>
#include <functional>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::cli {

/// A usage error found by a front end itself (exit 2), e.g. "--out x.xyz: exists".
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Option spellings that do not follow the rule `name` → `--name` with '_' → '-'.
using OptionSpellings = std::map<std::string, std::string, std::less<>>;

/// "--" + the name with every '_' as '-', unless `exceptions` spells it otherwise.
std::string option_spelling(std::string_view name, const OptionSpellings& exceptions = {});

/// "OPTION VALUE: RULE" (or "OPTION: RULE" for an empty value).
std::string usage_message(const ParameterError& error, const OptionSpellings& exceptions = {});

/// The one-line text of a runtime failure (exit 1): `error.what()`, except for
/// std::bad_alloc, whose text ("std::bad_alloc") tells a user nothing: "out of memory: …".
/// run_main shows every failure through it; a command that reports its own failures
/// (`sgmp convert`, `sgmp-reference`'s runs) does too.
std::string failure_message(const std::exception& error);

/// The message of a std::bad_alloc met while `what` was being read or built ("reading
/// FILE", "building the pack"): "WHAT: out of memory: …".
std::string out_of_memory_message(const std::string& what);

/// Runs f() and returns what it returns; a std::bad_alloc thrown inside becomes a
/// std::runtime_error with out_of_memory_message(what), so the one line a user sees names
/// what was being read or built (exit 1).
template <class F>
decltype(auto) while_doing(const std::string& what, F&& f) {
    try {
        return f();
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(out_of_memory_message(what));
    }
}

/// The most bytes of a message a program prints (before escaping: at most 4 times as many
/// after): a longer one (an error quoting a 16 MiB line) keeps its start and its end
/// (excerpt, input_error.hpp).
inline constexpr std::size_t kMaxMessageBytes = 1000;

/// Runs `parse` (which parses the command line into `app`) and then `body` (the
/// program's work, returning its exit status), mapping every exception to its one-line
/// message and exit status as in the table above.
int run_main(std::string_view program, CLI::App& app, const std::function<void()>& parse,
             const std::function<int()>& body, const OptionSpellings& exceptions = {});

}  // namespace sgmp::cli
