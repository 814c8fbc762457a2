#pragma once
/// @file dem_parameters.hpp
/// The DEM parameters of each reference class, as its pours record them in their headers,
/// for the report's table: the rows of the pour's parameter table
/// (reference/pour_parameters.hpp) in the groups `identity` (without the seed), `start`,
/// `material` and `numerics`, plus the contact model and the LIGGGHTS version. A class
/// whose pours share a value shows it; one whose pours differ shows up to three values
/// ("a / b / c"), else their count; one without the key, "—". Keys no pour records are
/// left out.
#include <string>
#include <vector>

#include "sgmp/report/agreement.hpp"

namespace sgmp::report {

struct DemParameterTable {
    std::vector<std::string> classes;              ///< reference labels that hold DEM pours
    std::vector<std::string> keys;                 ///< header keys, in table order
    std::vector<std::vector<std::string>> values;  ///< [key][class]
};

/// The table of the groups of `report` labelled `references` that hold LIGGGHTS pours
/// (generator=liggghts); empty when none does.
DemParameterTable dem_parameter_table(const Report& report,
                                      const std::vector<std::string>& references);

}  // namespace sgmp::report
