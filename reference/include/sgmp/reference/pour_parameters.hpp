#pragma once
/// @file pour_parameters.hpp
/// The parameter table of a LIGGGHTS pour (parameter_table.hpp): every member of PourParams
/// that a user sets, with its name, parse, format, rule and help. `PourParams::validate`,
/// the pack header's record and the options of `sgmp-reference pour` and `settle` iterate
/// over it.
///
/// Groups, in the header's order: `count`; `identity` (φ*, μ, seed, tangential damping);
/// `start` (the cloud's solid fraction, or an arrangement's jitter); `material` (e, μ_r, E, ν,
/// ρ, g); `numerics` (time step, settling test, time cap); `parallel` (ranks, processor grid).
/// Header keys carry their SI unit where the option does not (`youngs_modulus_pa`).
#include <string_view>
#include <vector>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/parameter_table.hpp"
#include "sgmp/reference/pour_params.hpp"

namespace sgmp::reference {

/// The pour's checks need nothing beyond its parameters.
struct PourCheckContext {};

using PourParameter = ParameterRow<PourParams, PourCheckContext>;

/// Every row, in the header's order.
const std::vector<PourParameter>& pour_parameters();

/// Records the rows of `group` that the parameters record, in table order, under their
/// header keys.
void record_pour_parameters(const PourParams& params, std::string_view group, Metadata& metadata);

}  // namespace sgmp::reference
