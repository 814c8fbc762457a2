#pragma once
/// @file parameters.hpp
/// The pack parameters a sweep can vary: every option of `sgmp pack` that shapes a pack
/// (count, arrangement, φ*, size modes, the protocol and the relaxation), by the name pack
/// headers record (`phi_target`; the command line spells it `--phi-target`).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "sgmp/engine/make_pack.hpp"

namespace sgmp::batch {

struct Parameter {
    std::string name;           // header / summary column name, snake_case
    std::string default_value;  // as `sgmp pack` defaults it ("" for count, arrangement)
    bool list_valued = false;   // its value holds commas (sweep_stages, size_modes)
};

/// Every sweepable parameter, in the fixed order of jobs, summary columns and patterns.
const std::vector<Parameter>& parameters();

/// The index of parameter `name` (snake_case or the option's kebab-case), or npos.
std::size_t parameter_index(std::string_view name);

/// One value per parameter, in parameters() order.
using ParameterValues = std::vector<std::string>;

/// The pack request the values stand for (seed included). Throws std::invalid_argument
/// with a one-line message naming the option, the value and the rule.
engine::PackRequest to_request(const ParameterValues& values, std::uint64_t seed);

}  // namespace sgmp::batch
