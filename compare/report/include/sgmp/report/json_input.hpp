#pragma once
/// @file json_input.hpp
/// JSON text of an input file (a baseline, a metrics file) parsed into one-line errors.

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "sgmp/pack/input_error.hpp"

namespace sgmp::report {

/// `text` parsed as JSON. Every failure of nlohmann's parser — bad syntax, and a number
/// beyond a double ("number overflow parsing '0.01e30802'", its out_of_range.406, which
/// escaped as a message naming no file) — is an InputError naming `source` and the rule.
template <class Json = nlohmann::json>
Json parse_json_input(std::string_view text, const std::string& source) {
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        std::string reason = error.what();
        const auto bracket = reason.find("] ");  // "[json.exception.parse_error.101] …"
        if (reason.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos) {
            reason.erase(0, bracket + 2);
        }
        throw InputError(source, 0, "not valid JSON (numbers must fit a double): " + reason);
    }
}

}  // namespace sgmp::report
