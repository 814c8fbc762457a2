#pragma once
/// @file make_pack.hpp
/// Building a whole pack: size the particles (thesis sizing rule), lay out the starting
/// arrangement, drop every particle in id order with the protocol, and record full
/// provenance. Same request ⇒ same pack, bit for bit: one `Random(seed)` stream feeds, in
/// this order, the size draw (multi-modal only), the colours, the loose-random positions and
/// the protocol's random choices. So for equal spheres the starting arrangement of a pack is
/// exactly `make_arrangement(arrangement, count, diameter_for_count(count, φ*),
/// Random(seed))` — what a reference pour started from the same state uses.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "sgmp/engine/arrangement.hpp"
#include "sgmp/engine/equilibrium_certificate.hpp"
#include "sgmp/engine/protocol_params.hpp"
#include "sgmp/engine/relax.hpp"
#include "sgmp/engine/relax_params.hpp"
#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/pack.hpp"
#include "sgmp/pack/sides.hpp"
#include "sgmp/pack/size_modes.hpp"

namespace sgmp::engine {

struct PackRequest {
    std::size_t count = 1002;
    Arrangement arrangement = Arrangement::LargeDense;
    std::uint64_t seed = 1;
    /// φ*: N/3 spheres fill the control volume at this fraction (sets d).
    double phi_target = kThesisPhiTarget;
    ProtocolParams protocol;
    /// Size distribution (size_modes.hpp); the default single mode is the thesis' equal
    /// spheres. The header's `diameter` is the scale s (the diameter of relative size 1).
    std::vector<SizeMode> size_modes = std::vector<SizeMode>(1);
    /// What the modes' fractions mean (number, volume or mass fractions).
    FractionBasis fraction_basis = FractionBasis::Number;
    /// Where the modes came from (a size-distribution file's name), for the header only.
    std::string size_distribution;
    /// The largest species' diameter in a physical unit, "200 um" (size_modes.hpp,
    /// parse_physical_length): from a CSV whose diameter column names its unit, or stated.
    /// `sgmp convert --length-unit` then scales the pack without --length-scale.
    std::string largest_diameter;
    /// The order a blend's particles drop in (drop_order.hpp): stratified, so every height
    /// of the deposit gets the blend's composition.
    DropOrder drop_order = DropOrder::Stratified;
    /// Relaxation after deposition (relax.hpp); none by default.
    RelaxParams relax;
    /// The container's lateral sides (sides.hpp): the thesis' walls by default.
    Sides sides = Sides::Walls;
};

/// What happened during packing (also recorded in the pack's metadata).
struct PackStats {
    double diameter = 0.0;
    double start_height = 0.0;
    long long moves = 0;         ///< sweep-and-move cycles over all particles
    std::size_t on_floor = 0;    ///< particles fixed by the floor
    std::size_t at_wall = 0;     ///< particles fixed by a wall
    std::size_t resting = 0;     ///< particles left by a sweep with no free position
    std::size_t stalled = 0;     ///< particles that moved stall_moves times without falling
    std::size_t move_limit = 0;  ///< particles that reached max_moves
    RelaxStats relax;            ///< the relaxation's, when one was asked for
    /// The relaxation's equilibrium certificate (its per-sphere fields empty).
    std::optional<EquilibriumCertificate> certificate;
    double certificate_seconds = 0.0;  ///< wall clock of the certificate (not recorded)
};

/// Called as (particles dropped, total) now and then while packing.
using ProgressCallback = std::function<void(std::size_t, std::size_t)>;

/// Checks every parameter of the request; throws ParameterError (the parameter's header
/// name, its value, the rule) for the first that breaks its rule.
void validate(const PackRequest& request);

/// The pack made by the request, with metadata: generator=sgmp, version, count, diameter,
/// phi_target, arrangement, seed, every protocol parameter, container, start_height and
/// the statistics; with a relaxation, its parameters and statistics follow (`relax_*`),
/// then its equilibrium certificate (`certified`, `certificate`, `certificate_*`:
/// equilibrium_certificate.hpp; frictional at the relaxation's own μ). Throws
/// ParameterError (see `validate`) for bad requests. `relax_progress` follows the
/// relaxation (relax.hpp); neither callback changes the pack.
Pack make_pack(const PackRequest& request, const ProgressCallback& progress = {},
               PackStats* stats = nullptr, const RelaxProgressCallback& relax_progress = {});

/// The starting arrangement alone as a pack (ids, colours, positions before packing),
/// with the same provenance keys minus the protocol's.
Pack make_start_pack(const PackRequest& request);

}  // namespace sgmp::engine
