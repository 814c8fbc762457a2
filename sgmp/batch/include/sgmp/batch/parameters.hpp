#pragma once
/// @file parameters.hpp
/// The pack parameters a sweep can vary: every row of the pack parameter table
/// (sgmp/engine/pack_parameters.hpp) but the seed, by the name pack headers record
/// (`phi_target`; the command line spells it `--phi-target`).

#include <cstddef>
#include <functional>
#include <map>
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

/// Every sweepable parameter, in the table's fixed order of jobs, summary columns and patterns.
const std::vector<Parameter>& parameters();

/// The index of parameter `name` (snake_case or the option's kebab-case), or npos.
std::size_t parameter_index(std::string_view name);

/// One value per parameter, in parameters() order.
using ParameterValues = std::vector<std::string>;

/// The text of the size-distribution files a grid names, by the name given: the front end
/// reads them (the library opens no file).
using DistributionFiles = std::map<std::string, std::string, std::less<>>;

/// The pack request the values stand for (seed included). A size_distribution that is not a
/// `lognormal:` spec is looked up in `files` and parsed as a CSV file
/// (sgmp::parse_size_distribution_csv). Throws ParameterError (the
/// parameter's name, the value, the rule) for a value its row refuses or a request that
/// breaks a rule; std::invalid_argument when `values` does not hold one value per parameter.
engine::PackRequest to_request(const ParameterValues& values, std::uint64_t seed,
                               const DistributionFiles& files = {});

}  // namespace sgmp::batch
