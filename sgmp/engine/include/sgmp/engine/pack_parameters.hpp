#pragma once
/// @file pack_parameters.hpp
/// The parameter table of a pack request (parameter_table.hpp): every option of
/// `sgmp pack`, `sgmp arrange`, `sgmp batch` and `sgmp.pack` that shapes a pack, with its
/// name, parse, format, rule and help. `validate(PackRequest)` and the pack header's
/// record iterate over it, and so do the front ends.
///
/// Groups, in the header's order: `count`; `request` (φ*, arrangement, seed, sizes); `protocol`
/// (thesis chapter 4 and §10.2); `relax` (relax_params.hpp; recorded only with a
/// relaxation, μ and k_t/k only with the frictional one).
#include <string_view>
#include <vector>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/parameter_table.hpp"

namespace sgmp::engine {

/// What the rows' checks need beyond the request: the smallest diameter it gives (the step
/// fall's step must be below it).
struct PackCheckContext {
    double smallest_diameter = 0.0;
};

using PackParameter = ParameterRow<PackRequest, PackCheckContext>;

/// Every row, in the fixed order of the header, of batch jobs and of summary columns.
const std::vector<PackParameter>& pack_parameters();

/// The row named `name` (snake_case or --kebab-case), or nullptr.
const PackParameter* find_pack_parameter(std::string_view name);

/// Sets the parameter `name` from its text; throws ParameterError (the row's name, the
/// text, the row's rule) when the row refuses the text or no row has that name.
void set_pack_parameter(PackRequest& request, std::string_view name, std::string_view text);

/// Records the rows of `group` that the request records, in table order, as
/// `name=format(request)`.
void record_pack_parameters(const PackRequest& request, std::string_view group, Metadata& metadata);

/// Checks the rows of `group`; throws ParameterError for the first that breaks its rule.
void check_pack_parameters(const PackRequest& request, std::string_view group,
                           const PackCheckContext& context);

}  // namespace sgmp::engine
