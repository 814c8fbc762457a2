#pragma once
/// @file relax_params.hpp
/// Parameters of the collective relaxation that may follow deposition (`--relax`): which
/// relaxation, the soft-contact stiffness schedule and the convergence criterion. Forces are
/// in units of m·g (m the mass of a sphere of relative size 1), stiffnesses in m·g/d (d the
/// diameter of relative size 1), so the numbers do not depend on N.
#include <optional>
#include <string>
#include <string_view>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/name_table.hpp"

namespace sgmp::engine {

enum class RelaxMode {
    /// No relaxation: the pack is the deposition's (the default).
    None,
    /// The whole pack relaxes under gravity to a mechanical equilibrium of frictionless
    /// spheres in the container (relax.hpp), then is finished as hard spheres.
    Frictionless,
    /// The same relaxation with Coulomb friction at every contact (relax.hpp, friction.hpp):
    /// Cundall–Strack tangential springs capped at |F_t| ≤ μ·F_n, spheres free to turn.
    Frictional,
};

/// How a frictionless relaxation ends (the frictional one always by LP).
enum class RelaxSettle {
    /// Sequential linear programming (hard_sphere_settle.hpp), the default.
    Lp,
    /// Non-smooth contact dynamics (contact_dynamics.hpp), its forces the certificate's witness.
    Dynamics,
};

/// Its rules, names and help are rows of the pack parameter table (pack_parameters.hpp).
struct RelaxParams {
    RelaxMode mode = RelaxMode::None;
    /// Contact stiffness k of the first stage, in m·g/d: a contact pressed by one weight m·g
    /// overlaps by d/k. Unset: the mode's (relax_schedule).
    std::optional<double> stiffness;
    /// Each later stage multiplies the stiffness by this factor (shrinking the overlaps).
    double stiffness_factor = 10.0;
    /// Number of stiffness stages (1 = the first stiffness only). Unset: the mode's
    /// (relax_schedule).
    std::optional<int> stages;
    /// Contact shell s: the soft spheres are (1 + s) times the real ones, so a soft contact
    /// pressed by less than s·k·(rᵢ + rⱼ)/d weights leaves the real spheres apart by a gap of
    /// at most s·(rᵢ + rⱼ); only deeper soft overlaps are left for the clearing and the
    /// hard-sphere finish. The default 0 makes the soft spheres the real ones: every loaded
    /// contact is parted by the clearing to touching (gaps of 10⁻⁹–10⁻⁷·d), so the pack's
    /// contacts count at δ = 10⁻⁶ as well (sgmp/engine/notes/relaxation-2026-11.md); with s =
    /// 3·10⁻⁴ they end as gaps of up to 3·10⁻⁴·d and Z(10⁻⁶) is 0.
    double shell = 0.0;
    /// A stage has converged when no sphere feels a net force above this, in m·g.
    double force_tolerance = 1e-4;
    /// Bound on the first stage's simulated time, in units of √(H/g) with H the pack's height
    /// above the floor when the relaxation starts (the time the collective collapse takes is
    /// of the order of a free fall through the pack). Unset: the mode's (relax_schedule).
    std::optional<double> time;
    /// Bound on each later stage's steps, in units of H/d_min (d_min the smallest diameter;
    /// at least 500 steps):
    /// the stiffer stages only relax the overlaps elastically, which takes a number of steps
    /// proportional to the pack's height in diameters. A stage reaching its bound ends
    /// unconverged (the pack records the force left, `relax_force_max`).
    double crossings = 40.0;
    /// Sliding friction μ of the frictional relaxation (pairs, walls and floor alike). Unused
    /// by the frictionless one. The default is the DEM frictional class's own, 0.5: the
    /// relaxation ends in a certified equilibrium at this μ, and no value was chosen by
    /// comparison with the pours (an earlier soft-only relaxation used 0.2, tuned against
    /// them: sgmp/engine/notes/relaxation-frictional-2026-11.md).
    double friction = 0.5;
    /// Tangential over normal stiffness k_t/k of the frictional relaxation. 2/7 makes the
    /// tangential oscillation of a contact as fast as the normal one for a solid sphere
    /// (I = 2/5·m·r²), the usual choice of linear-spring DEM.
    double tangential_ratio = 2.0 / 7.0;
    /// Bound on the settling that ends both relaxations: its LP iterations
    /// (hard_sphere_settle.hpp), or hundreds of time steps of the contact dynamics of
    /// `settle` = Dynamics (contact_dynamics.hpp; the default, 5000, allows 500,000). A
    /// settling that reaches it leaves a pack that is usually not an equilibrium: the
    /// certificate then says so (certified=false).
    int settle_limit = 5000;
    /// The frictionless settling: LP (the default) or contact dynamics.
    RelaxSettle settle = RelaxSettle::Lp;
};

/// The stiffness schedule a relaxation runs: the values given, else its mode's.
///
/// Frictionless: one stage at k = 2·10⁴ m·g/d, bounded at 200·√(H/g), a bound it did not
/// reach at N = 1002 (seeds 1–3) and 3000 (seed 1): the soft pack ends converged
/// (max|Fᵢ| ≤ 10⁻⁴ m·g) with overlaps of about 5·10⁻⁴·d, and the hard-sphere settling that
/// follows takes 2–6× fewer LPs than after the five unconverged stages from 2·10³
/// (sgmp/engine/notes/relax-certified-2026-12-06.md).
/// Frictional (and a request without relaxation): five stages from k = 2·10³ (ending at
/// 2·10⁷), the first bounded at 5·√(H/g): the frictional stages do not converge anyway
/// (relaxation-frictional-2026-11.md), and one converged stage at 2·10⁴ left the frictional
/// settling no faster.
struct RelaxSchedule {
    double stiffness = 0.0;  ///< of the first stage, m·g/d
    int stages = 0;
    double time = 0.0;  ///< bound on the first stage, in √(H/g)
};
RelaxSchedule relax_schedule(const RelaxParams& params);

/// The name table of the relaxation modes (name_table.hpp).
const NameTable<RelaxMode, 3>& relax_modes();
std::string_view to_string(RelaxMode mode);
std::optional<RelaxMode> parse_relax_mode(std::string_view text);
/// The name table of the frictionless settlings: lp, dynamics.
const NameTable<RelaxSettle, 2>& relax_settles();

}  // namespace sgmp::engine
