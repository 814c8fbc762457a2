#pragma once
// The message a command line shows for a refused parameter ("" when accepted): what
// `check` throws as ParameterError, spelled as an option by sgmp_cli (e.g. "--phi-target
// 0: must be in ...").
#include <string>

#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/parameter_error.hpp"

template <class Check>
std::string refusal(Check&& check) {
    try {
        check();
    } catch (const sgmp::ParameterError& e) {
        return sgmp::cli::usage_message(e);
    }
    return "";
}
