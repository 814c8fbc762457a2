// LIGGGHTS' result read back and checked (pour_result.hpp): the final dump's spheres at rest,
// one per id, each of its species' size, and a settled pour's invariants.
#include "pour_result.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sgmp/pack/pack_file.hpp"
#include "sgmp/reference/pour_parameters.hpp"

namespace sgmp::reference::detail {

namespace fs = std::filesystem;

namespace {

/// The LIGGGHTS result as messages name it: its file name only, since the work directory
/// that holds it is removed before the message is read.
constexpr const char* kResultName = "the LIGGGHTS result final.dump";

/// The result's own velocities agree with the settled report: its translational kinetic
/// energy per particle, m·v_rms²/2 over m·g·d, is below the settle threshold (the dump is
/// written at the step of the last check, with every digit, so it is the ratio LIGGGHTS
/// reported up to rounding). A result whose spheres still move was not settled.
void check_at_rest(const Pack& raw, const PourParams& p) {
    const std::optional<double> rms = raw.metadata.get_number("velocity_rms");
    if (!rms) {
        throw PourError(std::string(kResultName) +
                        " holds no velocities (vx vy vz), so it "
                        "cannot show that the pour settled");
    }
    const double d_metres = p.diameter() * kMetresPerUnit;
    // A blend's kinetic energy weighs each sphere by its mass; the rms alone bounds it from
    // below by the lightest sphere's: Σ mᵢvᵢ² ≥ m_min Σ vᵢ², so v_rms² / (2 g d) is at most
    // the threshold times m(d) / m_min.
    double allowed = 1.0;
    if (p.is_blend()) {
        const auto mass = [](double diameter, double density) {
            return density * diameter * diameter * diameter;
        };
        double lightest = std::numeric_limits<double>::infinity();
        for (const PourSpecies& s : p.species()) {
            lightest = std::min(lightest, mass(s.diameter, s.density));
        }
        allowed = mass(p.diameter(), p.density) / lightest;
    }
    const double ke_ratio = *rms * *rms / (2.0 * p.gravity * d_metres) / allowed;
    if (!(ke_ratio <= p.settle_threshold * (1.0 + 1e-9))) {
        throw PourError(
            "the LIGGGHTS result still moves: its velocities give KE_trans/(m g d) "
            "= " +
            format_number(ke_ratio) + ", above the settle threshold " +
            format_number(p.settle_threshold) + " it reported settled under");
    }
}

}  // namespace

/// The pack of LIGGGHTS' final dump `dump`: its `p.count` spheres at rest (check_at_rest),
/// ids 1..N in order, each of one species' radius; throws PourError otherwise.
Pack read_final(const fs::path& dump, const PourParams& p) {
    Pack raw;
    try {
        // The particles only: the walls are the input script's own (the container, recorded
        // by `record`), and check_settled measures every sphere against them, so the dump's
        // box is never taken for them (as written: no container is settled from the file).
        ReadOptions options;
        options.as_written = true;
        raw = read_pack_file(dump, options).pack;
    } catch (const std::exception& e) {
        std::string reason = e.what();
        for (std::size_t at = reason.find(dump.string()); at != std::string::npos;
             at = reason.find(dump.string())) {
            reason.replace(at, dump.string().size(), "final.dump");
        }
        throw PourError("cannot read the LIGGGHTS result: " + reason);
    }
    if (raw.particles.size() != p.count) {
        throw PourError(std::string(kResultName) + " holds " +
                        std::to_string(raw.particles.size()) + " spheres, not " +
                        std::to_string(p.count));
    }
    check_at_rest(raw, p);
    std::sort(raw.particles.begin(), raw.particles.end(),
              [](const Particle& a, const Particle& b) { return a.id < b.id; });
    const std::vector<PourSpecies> species = p.species();
    std::vector<std::size_t> found(species.size(), 0);
    for (std::size_t i = 0; i < raw.particles.size(); ++i) {
        Particle& particle = raw.particles[i];
        if (particle.id != static_cast<std::int64_t>(i + 1)) {
            throw PourError(std::string(kResultName) + ": particle ids are not 1.." +
                            std::to_string(p.count));
        }
        // Each sphere is of one species: its radius is that species' d/2, which it gets
        // exactly (the sizing rule's), and a blend's sphere its species number.
        std::size_t k = 0;
        while (k < species.size() && std::abs(particle.radius - species[k].diameter / 2.0) >
                                         1e-12 * species[k].diameter / 2.0) {
            ++k;
        }
        if (k == species.size()) {
            throw PourError(std::string(kResultName) + ": radius " +
                            format_number(particle.radius) +
                            " differs from d/2 = " + format_number(species.front().diameter / 2.0) +
                            (species.size() > 1 ? " and every other species' d/2" : ""));
        }
        ++found[k];
        particle.radius = species[k].diameter / 2.0;
        particle.species = species.size() > 1 ? static_cast<int>(k + 1) : 0;  // as sgmp pack
        particle.center /= kMetresPerUnit;  // metres to project units
    }
    for (std::size_t k = 0; k < species.size(); ++k) {
        if (found[k] != species[k].count) {
            throw PourError(std::string(kResultName) + " holds " + std::to_string(found[k]) +
                            " spheres of species " + std::to_string(k + 1) + ", not " +
                            std::to_string(species[k].count));
        }
    }
    Pack pack;
    pack.particles = std::move(raw.particles);
    return pack;
}

/// A settled pour's invariants, checked before anything is written: every sphere inside
/// the container and no pair overlapping by more than the soft-contact bound (all spheres
/// present and ids 1..N are checked by read_final). A DEM blow-up or a corrupt dump fails
/// here instead of entering the reference set.
void check_settled(const PourResult& result) {
    if (result.max_wall_penetration_over_d > kMaxSettledPenetrationOverD) {
        throw PourError("the LIGGGHTS result has a sphere " +
                        format_number(result.max_wall_penetration_over_d) +
                        " d through a wall or the floor; a settled pour stays within " +
                        format_number(kMaxSettledPenetrationOverD) + " d");
    }
    if (result.max_overlap_over_d > kMaxSettledOverlapOverD) {
        throw PourError("the LIGGGHTS result has two spheres overlapping by " +
                        format_number(result.max_overlap_over_d) +
                        " d; a settled pour stays within " +
                        format_number(kMaxSettledOverlapOverD) + " d");
    }
}

}  // namespace sgmp::reference::detail
