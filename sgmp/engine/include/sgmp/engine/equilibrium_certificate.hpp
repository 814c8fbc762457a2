#pragma once
/// @file equilibrium_certificate.hpp
/// The certificate that a pack of frictionless spheres is a mechanical equilibrium under
/// gravity: non-negative contact forces exist that balance every sphere's weight.
///
/// Contacts: every pair with gap |cᵢ − cⱼ| − rᵢ − rⱼ ≤ ε·d and every sphere whose gap to
/// a wall or the floor is ≤ ε·d (ε = gap_tolerance_over_d, default 10⁻⁶; d the scale
/// diameter). Each contact c carries a normal force f_c ≥ 0, in units of m·g (m the mass of
/// a sphere of diameter d); nᵢ,c is the unit normal pushing sphere i away from its partner
/// (the wall's inward normal for a wall). Sphere i of weight wᵢ = (dᵢ/d)³ has the residual
///
///     Rᵢ = Σ_c f_c·nᵢ,c − wᵢ·ŷ        (ŷ up; gravity −ŷ)
///
/// The forces are the least-L1 solution, min Σᵢ|Rᵢ|₁ over f ≥ 0, an LP solved exactly by
/// COIN-OR CLP's simplex (src/equilibrium_certificate.cpp): its optimum is 0 exactly when
/// forces balancing every sphere exist. Any f ≥ 0 is a valid set of forces, so a small
/// residual certifies; a large one says no forces exist (the tests check the optimum
/// against HiGHS's: tests/python/test_certificate.py).
/// The pack is certified when no pair or wall overlaps by more than ε·d and every |Rᵢ| is
/// at most residual_tolerance (default 10⁻³ m·g).
///
/// A witness: forces found by whoever made the pack (the settling's LP multipliers,
/// hard_sphere_settle.hpp) may be offered. They are tried first, on this pack's contacts
/// (a contact the witness does not name carries 0, a witness force not on a contact is
/// ignored, a negative one is refused); when they certify, the LP is not run. Either way
/// the forces reported are non-negative forces on the pack's contacts with the residuals
/// reported, so the certificate means the same; the witness only saves the LP (10 s at
/// N = 3000).
///
/// A frictional witness also names each contact's tangential force. The force on sphere
/// `first` is f·n + f_t (f_t projected on the contact's tangent plane at the final
/// positions); it is written exactly as non-negative multipliers of the pyramid's edges,
///
///     f·n + f_t = Σₖ βₖ·Eₖ,   β = (f − a − b)/8 on every edge, plus a on Eₖ and b on Eₖ₊₁,
///
/// where f_t/μ' = a·uₖ + b·uₖ₊₁ (uₖ = (Eₖ − n)/μ', the two edge directions either side of
/// f_t; a, b ≥ 0) and Σₖ uₖ = 0. It needs a + b ≤ f, i.e. f_t inside the pyramid's octagon
/// (a force in the inscribed cone, pyramid_inscribed_friction, always is); a tangential
/// force beyond it by rounding is scaled back onto its boundary. The residuals are then
/// those of the certificate's own system, so a witness certifies exactly when those edge
/// forces do.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sgmp/pack/geometry.hpp"
#include "sgmp/pack/particle.hpp"

namespace sgmp::engine {

struct CertificateOptions {
    double gap_tolerance_over_d = 1e-6;
    double residual_tolerance = 1e-3;  ///< in m·g
};

/// What a contact touches besides its sphere `first`.
enum class Partner : std::uint8_t { Sphere, Floor, XMin, XMax, ZMin, ZMax };

/// A contact's key: its spheres in increasing order, or its sphere and its wall (a
/// partner no sphere index reaches), (first << 32) | second.
std::uint64_t contact_key(std::size_t first, std::size_t second, Partner partner);

/// A sphere against one wall or the floor of the container: the gap between its surface
/// and the wall (negative when it penetrates), the wall's inward unit normal, and which.
struct WallGap {
    double gap = 0.0;
    Vec3 normal = Vec3::Zero();
    Partner wall = Partner::Floor;
};

/// The floor and the four walls, in that order (floor, x min, x max, z min, z max), as
/// seen from the sphere of centre c and radius r.
std::array<WallGap, 5> wall_gaps(const Vec3& c, double r, const Container& box);

/// A normal contact force, in m·g: between spheres `first` and `second` (either order), or
/// between sphere `first` and a wall or the floor.
struct ContactForce {
    std::size_t first = 0;
    std::size_t second = 0;  ///< used when partner is Sphere
    Partner partner = Partner::Sphere;
    double force = 0.0;
    /// The force on `first` across the normal, m·g (frictional witnesses; 0 otherwise).
    Vec3 tangential = Vec3::Zero();
};

struct EquilibriumCertificate {
    bool certified = false;
    double residual_max = 0.0;         ///< largest |Rᵢ|, m·g
    std::size_t worst_sphere = 0;      ///< index of the sphere with residual_max
    double residual_sum = 0.0;         ///< Σᵢ|Rᵢ|₁, the LP optimum, m·g
    double weight_sum = 0.0;           ///< Σᵢ wᵢ, m·g
    std::size_t contacts = 0;          ///< pairs plus wall and floor contacts
    std::size_t underconstrained = 0;  ///< spheres on fewer than 3 contacts
    double overlap_max_over_d = 0.0;   ///< deepest pair or wall overlap, over d
    std::vector<double> residual;      ///< |Rᵢ| per sphere, m·g
    std::vector<double> force;         ///< f_c per contact, m·g, in contact order
    bool by_witness = false;           ///< the offered witness certified; no LP was solved
};

/// Certifies `particles` (scale diameter `diameter`) in `container` as above, trying
/// `witness` first; throws std::invalid_argument for a diameter ≤ 0, tolerances out of
/// range or a negative witness force.
EquilibriumCertificate certify_frictionless(const std::vector<Particle>& particles,
                                            const Container& container, double diameter,
                                            const CertificateOptions& options = {},
                                            std::span<const ContactForce> witness = {});

/// The frictional certificate at sliding friction μ: each contact force lies in the
/// pyramid of 8 edges n + μ'·(cos θₖ t₁ + sin θₖ t₂), μ' = μ·cos(π/8), inscribed in the
/// Coulomb cone |f_t| ≤ μ·f_n (so any forces it finds obey Coulomb's law), and every sphere
/// balances force and torque: the residual of sphere i is √(|R_F,i|² + |R_T,i/d|²), its
/// torque taken about the centre, the contact at the surface point cᵢ − rᵢ·n. No rolling
/// resistance. Spheres on no contact are counted as underconstrained. A `witness` (normal
/// and tangential forces, above) is tried first, as for the frictionless certificate.
EquilibriumCertificate certify_frictional(const std::vector<Particle>& particles,
                                          const Container& container, double diameter,
                                          double friction, const CertificateOptions& options = {},
                                          std::span<const ContactForce> witness = {});

}  // namespace sgmp::engine
