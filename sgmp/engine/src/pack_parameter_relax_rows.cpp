// The relaxation's rows of the pack request (pack_parameters.hpp): the mode, the soft
// stage's stiffness schedule and stopping rules, the hard-sphere settling and friction.
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "pack_parameter_rows.hpp"
#include "sgmp/engine/hard_sphere_settle.hpp"

namespace sgmp::engine::pack_rows {
namespace {

bool relaxed(const PackRequest& r) {
    return r.relax.mode != RelaxMode::None;
}
bool frictional(const PackRequest& r) {
    return r.relax.mode == RelaxMode::Frictional;
}

void check_relax_stages(const PackRequest& r, const PackCheckContext&) {
    const RelaxSchedule x = relax_schedule(r.relax);
    if (x.stages < 1 || x.stages > 10) {
        refuse("relax_stages", std::to_string(x.stages), "must be 1 to 10");
    }
    if (!(x.stiffness * std::pow(r.relax.stiffness_factor, x.stages - 1) <= 1e12)) {
        refuse("relax_stages", std::to_string(x.stages),
               "the last stage's stiffness must not exceed 1e12 m*g/d");
    }
}

/// A row of the stiffness schedule (relax_schedule): unset by default, so that each mode
/// runs its own; `member` reaches the optional the request holds (the number or whole-number
/// row's parse and rule), and the header records the value the relaxation runs (`effective`).
template <class T, class Member>
Row scheduled(std::string name, Member member, std::function<T(const RelaxSchedule&)> effective,
              std::string help, Check check) {
    Row row = [&] {
        if constexpr (std::is_integral_v<T>) {
            return whole(std::move(name), "relax", member, std::move(help), std::move(check));
        } else {
            return number(std::move(name), "relax", member, std::move(help), std::move(check));
        }
    }();
    row.format = [effective](const PackRequest& r) {
        const T value = effective(relax_schedule(r.relax));
        if constexpr (std::is_integral_v<T>) {
            return std::to_string(value);
        } else {
            return format_number(value);
        }
    };
    row.unset_by_default = true;
    return row;
}

/// The relaxation mode's row; a mode other than none needs COIN-OR CLP.
Row relax_mode_row() {
    const std::string g = "relax";
    Row relax = choice(
        "relax", g, [](auto& r) -> auto& { return r.relax.mode; }, [] { return relax_modes(); },
        "after deposition: none | frictionless (relax the whole pack under gravity to an "
        "equilibrium of frictionless soft spheres by FIRE energy minimisation, then settle it as "
        "hard spheres into a certified equilibrium by linear programming; about 5 s at N = 1002, "
        "2 min at N = 3000) | frictional (the same with Coulomb friction at --relax-friction: "
        "tangential springs capped at mu*F_n, then a frictional hard-sphere settling into a "
        "certified equilibrium; slower still)");
    relax.check = [](const PackRequest& r, const PackCheckContext&) {
        if (r.relax.mode != RelaxMode::None && !lp_solver_available()) {
            refuse("relax", std::string(to_string(r.relax.mode)),
                   "needs COIN-OR CLP, which this build lacks (SGMP_WITH_CLP=OFF)");
        }
    };
    return relax;
}

/// The soft stage's rows: the stiffness schedule, the contact shell and the stopping rules.
void add_soft_stage_rows(std::vector<Row>& rows) {
    const std::string g = "relax";
    rows.push_back(scheduled<double>(
        "relax_stiffness", [](auto& r) -> auto& { return r.relax.stiffness; },
        [](const RelaxSchedule& x) { return x.stiffness; },
        "contact stiffness k of the first relaxation stage in m*g/d (a contact carrying one "
        "weight m*g overlaps by d/k); default 2e4 frictionless, 2e3 frictional",
        in_range(
            "relax_stiffness",
            [](const PackRequest& r) { return relax_schedule(r.relax).stiffness; }, 1e2, 1e12,
            "must be in [100, 1e12] (m*g/d)")));
    rows.push_back(number(
        "relax_stiffness_factor", g, [](auto& r) -> auto& { return r.relax.stiffness_factor; },
        "each later relaxation stage multiplies the stiffness by this factor",
        in_range(
            "relax_stiffness_factor", [](const PackRequest& r) { return r.relax.stiffness_factor; },
            1.0, 1e6, "must be in [1, 1e6]")));
    rows.push_back(scheduled<int>(
        "relax_stages", [](auto& r) -> auto& { return r.relax.stages; },
        [](const RelaxSchedule& x) { return x.stages; },
        "number of stiffness stages (1 to 10); default 1 frictionless (run to convergence), 5 "
        "frictional",
        check_relax_stages));
    rows.push_back(number(
        "relax_shell", g, [](auto& r) -> auto& { return r.relax.shell; },
        "contact shell s in [0, 0.01]: the soft spheres are (1+s) times the real ones, so soft "
        "contacts end as gaps of at most s*(ri+rj); 0: contacts end touching",
        in_range(
            "relax_shell", [](const PackRequest& r) { return r.relax.shell; }, 0.0, 0.01,
            "must be in [0, 0.01]")));
    rows.push_back(number(
        "relax_force_tolerance", g, [](auto& r) -> auto& { return r.relax.force_tolerance; },
        "a stage has converged when no sphere feels a net force above this, in m*g (m the mass "
        "of a sphere of relative size 1)",
        [](const PackRequest& r, const PackCheckContext&) {
            const double t = r.relax.force_tolerance;
            if (!(t > 0.0) || !(t <= 1.0)) {
                refuse("relax_force_tolerance", format_number(t), "must be in (0, 1] (m*g)");
            }
        }));
    rows.push_back(scheduled<double>(
        "relax_time", [](auto& r) -> auto& { return r.relax.time; },
        [](const RelaxSchedule& x) { return x.time; },
        "bound on the first stage's simulated time, in units of sqrt(H/g) (H: the pack's height "
        "above the floor); default 200 frictionless, 5 frictional",
        [](const PackRequest& r, const PackCheckContext&) {
            const double time = relax_schedule(r.relax).time;
            if (!(time > 0.0) || !(time <= 1e4)) {
                refuse("relax_time", format_number(time), "must be in (0, 10000]");
            }
        }));
    rows.push_back(number(
        "relax_crossings", g, [](auto& r) -> auto& { return r.relax.crossings; },
        "bound on each later stage's steps, in units of H/d (the elastic relaxation crosses the "
        "pack's height); the pack records the force left (relax_force_max)",
        [](const PackRequest& r, const PackCheckContext&) {
            if (!(r.relax.crossings > 0.0) || !(r.relax.crossings <= 1e4)) {
                refuse("relax_crossings", format_number(r.relax.crossings),
                       "must be in (0, 10000]");
            }
        }));
}

/// The rows of the hard-sphere settling's method and of friction (--relax frictional).
void add_settle_and_friction_rows(std::vector<Row>& rows) {
    const std::string g = "relax";
    Row settle = choice(
        "relax_settle", g, [](auto& r) -> auto& { return r.relax.settle; },
        [] { return relax_settles(); },
        "how --relax settles as hard spheres: lp (sequential linear programming, the default) "
        "or dynamics (non-smooth contact dynamics; frictionless: each step's contacts by "
        "SSOR-preconditioned MPRGP, its forces the certificate's witness, 2-3x slower than lp "
        "at N = 1002, does not converge at N = 3000; frictional: NSGS with a Coulomb solve per "
        "contact in the cone inside the certificate's pyramid, mu*cos^2(pi/8), its force "
        "vectors the certificate's witness, about 6-50 CPU s at N = 150 where lp takes "
        "minutes: sgmp/engine/docs/relaxation.md)");
    settle.recorded = [](const PackRequest& r) {
        return r.relax.mode != RelaxMode::None && r.relax.settle != RelaxSettle::Lp;
    };
    settle.check = [](const PackRequest& r, const PackCheckContext&) {
        if (r.relax.settle == RelaxSettle::Dynamics && r.relax.mode == RelaxMode::None) {
            refuse("relax_settle", "dynamics", "needs --relax frictionless or frictional");
        }
    };
    rows.push_back(std::move(settle));
    Row friction = number(
        "relax_friction", g, [](auto& r) -> auto& { return r.relax.friction; },
        "sliding friction mu of --relax frictional (pairs and walls), in [0, 10]; the DEM "
        "frictional class's own mu, untuned",
        in_range(
            "relax_friction", [](const PackRequest& r) { return r.relax.friction; }, 0.0, 10.0,
            "must be in [0, 10]"));
    friction.recorded = frictional;
    rows.push_back(std::move(friction));
    Row tangential = number(
        "relax_tangential_ratio", g, [](auto& r) -> auto& { return r.relax.tangential_ratio; },
        "tangential over normal contact stiffness of --relax frictional, in (0, 1]",
        [](const PackRequest& r, const PackCheckContext&) {
            const double t = r.relax.tangential_ratio;
            if (!(t > 0.0) || !(t <= 1.0)) {
                refuse("relax_tangential_ratio", format_number(t), "must be in (0, 1]");
            }
        });
    tangential.recorded = frictional;
    rows.push_back(std::move(tangential));
}

}  // namespace

/// The relaxation's rows, each recorded only when the pack is relaxed (friction's only
/// when frictional; the settling method's only when not lp).
void add_relax_rows(std::vector<Row>& rows) {
    const std::string g = "relax";
    const std::size_t first = rows.size();
    rows.push_back(relax_mode_row());
    add_soft_stage_rows(rows);
    rows.push_back(whole(
        "relax_settle_limit", g, [](auto& r) -> auto& { return r.relax.settle_limit; },
        "bound on the LP iterations of the hard-sphere settling that ends the relaxation (1 to "
        "1000000; --relax-settle dynamics: hundreds of time steps); a pack that reaches it is "
        "usually not a certified equilibrium",
        [](const PackRequest& r, const PackCheckContext&) {
            if (r.relax.settle_limit < 1 || r.relax.settle_limit > 1000000) {
                refuse("relax_settle_limit", std::to_string(r.relax.settle_limit),
                       "must be between 1 and 1000000");
            }
        }));
    for (std::size_t i = first; i < rows.size(); ++i) {
        rows[i].recorded = relaxed;
    }
    add_settle_and_friction_rows(rows);
}

}  // namespace sgmp::engine::pack_rows
