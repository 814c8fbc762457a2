#include "sgmp/engine/make_pack.hpp"

#include <stdexcept>

#include "sgmp/engine/protocol.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::engine {

namespace {

void record_request(const PackRequest& request, double diameter, Metadata& m) {
    m.set("generator", "sgmp");
    m.set("version", version());
    m.set_integer("count", static_cast<long long>(request.count));
    m.set_number("diameter", diameter);
    m.set_number("phi_target", request.phi_target);
    m.set("arrangement", std::string(to_string(request.arrangement)));
    m.set("seed", std::to_string(request.seed));
}

}  // namespace

std::optional<std::string> validate(const PackRequest& request) {
    if (request.count < 1 || request.count > kMaxCount) {
        return "--count " + std::to_string(request.count) + ": must be between 1 and " +
               std::to_string(kMaxCount);
    }
    if (!(request.phi_target > 0.0) || !(request.phi_target <= kMaxPhiTargetAccepted)) {
        return "--phi-target " + format_number(request.phi_target) +
               ": must be in (0, 0.7405] (the densest packing of equal spheres)";
    }
    const double d = diameter_for_count(request.count, request.phi_target);
    if (!(d < kContainerSide)) {
        return "--count " + std::to_string(request.count) + ": the diameter " + format_number(d) +
               " it gives at phi-target " + format_number(request.phi_target) +
               " does not fit the 1.25-wide container";
    }
    return validate(request.protocol, d);
}

Pack make_start_pack(const PackRequest& request) {
    if (const auto error = validate(request)) {
        throw std::invalid_argument(*error);
    }
    const double d = diameter_for_count(request.count, request.phi_target);
    Random rng(request.seed);
    Pack pack;
    pack.particles = make_arrangement(request.arrangement, request.count, d, rng);
    record_request(request, d, pack.metadata);
    pack.metadata.set("stage", "start");
    pack.metadata.set("container", Container{}.to_string());
    pack.metadata.set_number("start_height", starting_height(pack.particles));
    return pack;
}

Pack make_pack(const PackRequest& request, const ProgressCallback& progress, PackStats* stats) {
    if (const auto error = validate(request)) {
        throw std::invalid_argument(*error);
    }
    const Container container;
    const double d = diameter_for_count(request.count, request.phi_target);
    Random rng(request.seed);
    std::vector<Particle> particles = make_arrangement(request.arrangement, request.count, d, rng);
    PackStats local;
    local.diameter = d;
    local.start_height = starting_height(particles, container);

    Protocol protocol(container, request.protocol, 0.5 * d);
    const std::size_t report_every = 1000;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const DropOutcome outcome = protocol.drop(particles[i], rng);
        particles[i].center = outcome.center;
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

    Pack pack;
    pack.particles = std::move(particles);
    Metadata& m = pack.metadata;
    record_request(request, d, m);
    record(request.protocol, m);
    m.set("container", container.to_string());
    m.set_number("start_height", local.start_height);
    m.set_integer("moves", local.moves);
    m.set_integer("fixed_floor", static_cast<long long>(local.on_floor));
    m.set_integer("fixed_wall", static_cast<long long>(local.at_wall));
    m.set_integer("resting", static_cast<long long>(local.resting));
    m.set_integer("stalled", static_cast<long long>(local.stalled));
    m.set_integer("move_limit", static_cast<long long>(local.move_limit));
    if (stats != nullptr) {
        *stats = local;
    }
    return pack;
}

}  // namespace sgmp::engine
