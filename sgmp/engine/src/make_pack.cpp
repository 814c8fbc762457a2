#include "sgmp/engine/make_pack.hpp"

#include "sgmp/pack/size_classes.hpp"

#include "sgmp/engine/equilibrium_certificate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "sgmp/engine/pack_parameters.hpp"
#include "sgmp/engine/protocol.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::engine {

namespace {

struct Sizes {
    double scale;
    double smallest;
    double largest;
};

/// The request's modes with number fractions (size_modes.hpp).
std::vector<SizeMode> modes_of(const PackRequest& request) {
    return number_fractions(request.size_modes, request.fraction_basis);
}

Sizes sizes_of(const PackRequest& request) {
    const std::vector<SizeMode> modes = modes_of(request);
    const double scale = diameter_scale(request.count, request.phi_target, modes);
    Sizes sizes{scale, INFINITY, 0.0};
    for (const SizeMode& m : modes) {
        if (m.fraction == 0.0) {
            continue;  // a species with no particle
        }
        sizes.smallest = std::min(sizes.smallest, m.relative_diameter * scale);
        sizes.largest = std::max(sizes.largest, m.relative_diameter * scale);
    }
    return sizes;
}

std::vector<Particle> starting_particles(const PackRequest& request, Random& rng) {
    const DrawnSizes drawn =
        draw_sizes(request.count, request.phi_target, modes_of(request), rng, request.drop_order);
    std::vector<Particle> particles = make_arrangement(request.arrangement, drawn.diameters, rng);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        particles[i].species = drawn.species[i];  // the arrangement keeps the drop order
    }
    return particles;
}

/// Comma-separated numbers.
std::string number_list(const std::vector<double>& values) {
    std::string text;
    for (const double v : values) {
        text += (text.empty() ? "" : ",") + format_number(v);
    }
    return text;
}

/// The realised blend: particles per species and their number, volume and (with densities)
/// mass fractions, from the deterministic counts (size_modes.hpp mode_counts).
void record_species(const PackRequest& request, Metadata& m) {
    const std::vector<SizeMode> modes = modes_of(request);
    if (modes.size() < 2) {
        return;
    }
    const std::vector<std::size_t> counts = mode_counts(request.count, modes);
    std::vector<double> number(modes.size());
    std::vector<double> volume(modes.size());
    std::vector<double> mass(modes.size());
    double n_total = 0.0;
    double v_total = 0.0;
    double m_total = 0.0;
    bool densities = true;
    std::string count_text;
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const double a = modes[i].relative_diameter;
        number[i] = static_cast<double>(counts[i]);
        volume[i] = number[i] * a * a * a;
        densities = densities && modes[i].density.has_value();
        mass[i] = volume[i] * modes[i].density.value_or(1.0);
        n_total += number[i];
        v_total += volume[i];
        m_total += mass[i];
        count_text += (i == 0 ? "" : ",") + std::to_string(counts[i]);
    }
    for (std::size_t i = 0; i < modes.size(); ++i) {
        number[i] /= n_total;
        volume[i] /= v_total;
        mass[i] /= m_total;
    }
    m.set("species_counts", count_text);
    m.set("species_number_fractions", number_list(number));
    m.set("species_volume_fractions", number_list(volume));
    if (densities) {
        m.set("species_mass_fractions", number_list(mass));
    }
}

void record_request(const PackRequest& request, double diameter, Metadata& m) {
    m.set("generator", "sgmp");
    m.set("version", version());
    record_pack_parameters(request, "count", m);
    m.set_number("diameter", diameter);
    record_pack_parameters(request, "request", m);
    record_species(request, m);
}

/// Hands memory freed inside the heap back to the system (glibc keeps it otherwise, and the
/// settled grid's blocks, freed after deposition, raised the peak memory of a 10^6 pack by
/// 8-24 MB as later allocations did not fit their place).
void release_free_memory() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

/// Drops every particle in id order with the protocol (the neighbour grid is freed on return).
void deposit(std::vector<Particle>& particles, const PackRequest& request,
             const Container& container, double r_max, Random& rng,
             const ProgressCallback& progress, PackStats& local) {
    // A wide blend (r_max > 2 r_min) keeps its small spheres in a grid of their own
    // (protocol.hpp), for the contact model none, whose rests need no further grid query.
    const SizeClasses sizes = size_classes(particles);  // size_classes.hpp
    const bool split = sizes.wide() && request.protocol.contact == ContactModel::None;
    Protocol protocol(container, request.protocol, r_max, split ? sizes.small_max_radius : 0.0);
    const std::size_t report_every = 1000;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const DropOutcome outcome = protocol.drop(particles[i], rng);
        particles[i].center = container.wrapped(outcome.center);
        protocol.settle(particles[i]);
        local.moves += outcome.moves;
        switch (outcome.reason) {
            case StopReason::Floor:
                ++local.on_floor;
                break;
            case StopReason::Wall:
                ++local.at_wall;
                break;
            case StopReason::NoFreeArc:
                ++local.resting;
                break;
            case StopReason::Stalled:
                ++local.stalled;
                break;
            case StopReason::MoveLimit:
                ++local.move_limit;
                break;
        }
        if (progress && ((i + 1) % report_every == 0 || i + 1 == particles.size())) {
            progress(i + 1, particles.size());
        }
    }
}

void record_relaxation(const PackRequest& request, const RelaxStats& stats, Metadata& m) {
    const RelaxParams& params = request.relax;
    if (params.mode == RelaxMode::None) {
        return;
    }
    record_pack_parameters(request, "relax", m);
    m.set_integer("relax_steps", stats.steps);
    m.set_integer("relax_stages_converged", stats.stages_converged);
    m.set_number("relax_force_max", stats.force_max);
    m.set_number("relax_overlap_max", stats.overlap_max);
    m.set_integer("relax_finish_lifted", stats.finish_lifted);
    m.set_number("relax_finish_move_max", stats.finish_move_max);
    m.set_number("relax_finish_move_mean", stats.finish_move_mean);
    m.set_integer("relax_settle_iterations", stats.settle_iterations);
    m.set("relax_settle_converged", stats.settle_converged ? "true" : "false");
    // How the settling ended. Frictionless (contact dynamics): its residual met the tolerance,
    // it stalled at its smallest step, or --relax-settle-limit stopped it. Frictional (LP):
    // its trust region shrank away, a step moved nothing, the LP solver failed, or the limit.
    const bool dynamics = params.settle == RelaxSettle::Dynamics;
    m.set("relax_settle_end", dynamics                     ? (stats.settle_converged ? "residual"
                                                              : stats.settle_stalled ? "stalled"
                                                                                     : "limit")
                              : stats.settle_ended_still   ? "still"
                              : stats.settle_converged     ? "trust-region"
                              : stats.settle_solver_failed ? "solver-failed"
                                                           : "limit");
    if (dynamics) {
        m.set_integer("relax_settle_sweeps", stats.settle_sweeps);
        m.set_number("relax_settle_residual", stats.settle_residual);
        m.set_integer("relax_settle_returns", stats.settle_returns);
        m.set_integer("relax_settle_stall_returns", stats.settle_stall_returns);
        m.set_integer("relax_settle_closing_steps", stats.settle_closing_steps);
    }
    m.set_number("relax_settle_move_max", stats.settle_move_max);
    m.set_number("relax_settle_energy_drop", stats.settle_energy_drop);
}

/// The equilibrium certificate's header keys (equilibrium_certificate.hpp).
void record_certificate(const std::optional<EquilibriumCertificate>& c, const RelaxParams& relax,
                        const std::vector<Particle>& particles, Metadata& m) {
    if (!c) {
        return;
    }
    const CertificateOptions options;
    m.set("certified", c->certified ? "true" : "false");
    if (relax.mode == RelaxMode::Frictional) {
        m.set("certificate", "frictional");
        m.set_number("certificate_friction", relax.friction);
    } else {
        m.set("certificate", "frictionless");
    }
    // Which forces balanced: the settling's own multipliers, checked, or the certificate LP's.
    m.set("certificate_forces", c->by_witness ? "settling-witness" : "lp");
    m.set_number("certificate_gap_tolerance", options.gap_tolerance_over_d);
    m.set_number("certificate_residual_tolerance", options.residual_tolerance);
    m.set_number("certificate_residual_max", c->residual_max);
    m.set_number("certificate_residual_sum", c->residual_sum);
    m.set_integer("certificate_worst_id", particles.at(c->worst_sphere).id);
    m.set_integer("certificate_contacts", static_cast<long long>(c->contacts));
    m.set_integer("certificate_underconstrained", static_cast<long long>(c->underconstrained));
    m.set_number("certificate_overlap_max", c->overlap_max_over_d);
}

}  // namespace

void validate(const PackRequest& request) {
    // The count's range, φ*, the sizes and their basis first: the diameters follow from them.
    check_pack_parameters(request, "count", {});
    check_pack_parameters(request, "request", {});
    const Sizes sizes = sizes_of(request);
    if (!(sizes.largest < kContainerSide)) {
        throw ParameterError("count", std::to_string(request.count),
                             "the diameter " + format_number(sizes.largest) +
                                 " it gives at phi_target " + format_number(request.phi_target) +
                                 " does not fit the 1.25-wide container");
    }
    if (request.sides == Sides::Periodic) {
        const std::string rule = periodic_cell_rule(sizes.largest, kContainerSide);
        if (!rule.empty()) {
            throw ParameterError("sides", "periodic", rule);
        }
    }
    check_pack_parameters(request, "protocol", {sizes.smallest});
    check_pack_parameters(request, "relax", {sizes.smallest});
}

Pack make_start_pack(const PackRequest& request) {
    validate(request);
    Random rng(request.seed);
    Pack pack;
    pack.particles = starting_particles(request, rng);
    record_request(request, sizes_of(request).scale, pack.metadata);
    pack.metadata.set("stage", "start");
    pack.metadata.set("container", Container{}.to_string());
    pack.metadata.set_number("start_height", starting_height(pack.particles));
    return pack;
}

Pack make_pack(const PackRequest& request, const ProgressCallback& progress, PackStats* stats,
               const RelaxProgressCallback& relax_progress) {
    validate(request);
    Container container;
    container.periodic = request.sides == Sides::Periodic;
    const Sizes sizes = sizes_of(request);
    const double d = sizes.scale;
    Random rng(request.seed);
    std::vector<Particle> particles = starting_particles(request, rng);
    PackStats local;
    local.diameter = d;
    local.start_height = starting_height(particles, container);

    deposit(particles, request, container, 0.5 * sizes.largest, rng, progress, local);
    release_free_memory();  // the neighbour grid's, before the relaxation and the checks
    if (request.relax.mode != RelaxMode::None) {
        local.relax = relax_pack(particles, container, request.relax, d, relax_progress);
        const auto certifying = std::chrono::steady_clock::now();
        local.certificate =
            request.relax.mode == RelaxMode::Frictionless
                ? certify_frictionless(particles, container, d, {}, local.relax.settle_forces)
                : certify_frictional(particles, container, d, request.relax.friction, {},
                                     local.relax.settle_forces);
        local.certificate_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - certifying).count();
        local.relax.settle_forces.clear();
        local.relax.settle_forces.shrink_to_fit();
        local.certificate->residual.clear();  // the summary is kept, not the fields
        local.certificate->force.clear();
    }

    Pack pack;
    pack.particles = std::move(particles);
    Metadata& m = pack.metadata;
    record_request(request, d, m);
    record_pack_parameters(request, "protocol", m);
    m.set("container", container.to_string());
    m.set_number("start_height", local.start_height);
    m.set_integer("moves", local.moves);
    m.set_integer("fixed_floor", static_cast<long long>(local.on_floor));
    m.set_integer("fixed_wall", static_cast<long long>(local.at_wall));
    m.set_integer("resting", static_cast<long long>(local.resting));
    m.set_integer("stalled", static_cast<long long>(local.stalled));
    m.set_integer("move_limit", static_cast<long long>(local.move_limit));
    record_relaxation(request, local.relax, m);
    if (request.relax.mode != RelaxMode::None) {
        record_certificate(local.certificate, request.relax, pack.particles, m);
    }
    if (stats != nullptr) {
        *stats = local;
    }
    return pack;
}

}  // namespace sgmp::engine
