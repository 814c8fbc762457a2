#pragma once
/// @file protocol_params.hpp
/// Every parameter of the Spin Gap Move Protocol (thesis chapter 4) and of the
/// improvements its §10.2 asks for. Defaults are the thesis' protocol.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/name_table.hpp"

namespace sgmp::engine {

/// How a particle falls until its first contact.
enum class FallMode {
    /// Jump straight to the first contact below (analytic contact height against every
    /// sphere in the column below, and the floor): the particle ends touching it.
    Exact,
    /// The thesis' fall: steps of `fall_step`; the particle stops at the last step that
    /// does not collide, so it ends less than one step above its support. Computed in
    /// closed form (k = ⌊(y0 − y_contact)/step⌋ steps), identical to stepping but O(1).
    Step,
};

/// Which free arc of the sweep the particle moves toward.
enum class GapRule {
    /// The largest free arc (thesis); ties go to the arc met first from angle 0.
    Largest,
    /// A free arc chosen uniformly at random (thesis §4.2, "random gap selection").
    Random,
};

/// What happens to a particle the protocol leaves resting (no free arc, stalled, move limit);
/// particles fixed by the floor or a wall stay as they are.
enum class ContactModel {
    /// Nothing: the particle stays where the protocol left it (thesis).
    None,
    /// §10.2 contact model: the resting particle is settled into contact with its supports —
    /// dropped exactly onto the sphere below (closing a step-mode gap) and then rolled
    /// down over that sphere until it touches a second one (or the floor or a wall).
    Settle,
    /// A fuller contact model: the resting particle rolls down over the settled spheres
    /// until it rests stably on three (or two at the bottom of their circle), or touches the
    /// floor or a wall (rolling.hpp).
    Roll,
};

/// How the side walls act on a particle that a sweep move brings against them.
enum class WallRule {
    /// Thesis §4.2: a particle that reaches a wall stops there and is fixed.
    Fix,
    /// Walls are obstacles like particles: sweep positions crossing a wall are not free.
    Block,
};

struct ProtocolParams {
    /// Sweep radius = d / circle_factor (thesis: 50).
    double circle_factor = 50.0;
    /// Positions tested on the sweep circle, per stage. One stage of 120 (3° apart) is the
    /// thesis; several stages (e.g. 8,120,720) try the next stage only when the previous
    /// one found no free position (§10.2 multi-stage sweep).
    std::vector<int> sweep_stages = {120};
    /// Size of the thesis' lower columnar neighbour list (10). Recorded for provenance only:
    /// the fall here scans every sphere of the column below (protocol.hpp), so the first
    /// contact is never missed and no value of this parameter changes a result.
    int lower_neighbours = 10;
    GapRule gap = GapRule::Largest;
    FallMode fall = FallMode::Exact;
    /// Downward increment of the step fall (thesis: 0.001, in control-volume sides).
    double fall_step = 0.001;
    ContactModel contact = ContactModel::None;
    /// Momentum weight m ∈ [0, 1): the move goes to the free position of the chosen arc
    /// closest in direction to (1 − m)·bisector + m·previous move. 0 is the thesis.
    double momentum = 0.0;
    WallRule walls = WallRule::Fix;
    /// A particle that makes this many consecutive moves without falling at all rests where
    /// it is (it is within one fall step of its support). The thesis does not say how its
    /// step fall ends a particle that shuffles between places it cannot fall from — with a
    /// step fall, a particle hovering between supports can oscillate forever; 50 moves
    /// carry a particle one diameter at the thesis' circle factor.
    long stall_moves = 50;
    /// Safety bound on sweep-and-move cycles per particle; a particle reaching it rests
    /// where its last fall left it (it is supported there).
    long max_moves = 100000;
};

/// Largest number of sweep positions in one stage.
inline constexpr int kMaxSweepPositions = 1000000;

/// Checks the parameters for particles of diameter `diameter` with the rows of the pack
/// parameter table (pack_parameters.hpp); throws ParameterError (the parameter's header
/// name, its value, the rule) for the first that breaks its rule.
void validate(const ProtocolParams& params, double diameter);

/// The name tables of the protocol's choices (name_table.hpp).
const NameTable<FallMode, 2>& fall_modes();
const NameTable<GapRule, 2>& gap_rules();
const NameTable<ContactModel, 3>& contact_models();
const NameTable<WallRule, 2>& wall_rules();

std::string_view to_string(FallMode mode);
std::string_view to_string(GapRule rule);
std::string_view to_string(ContactModel model);
std::string_view to_string(WallRule rule);
std::optional<FallMode> parse_fall_mode(std::string_view text);
std::optional<GapRule> parse_gap_rule(std::string_view text);
std::optional<ContactModel> parse_contact_model(std::string_view text);
std::optional<WallRule> parse_wall_rule(std::string_view text);
/// "8,120,720" for the stages; parse returns nullopt for anything but positive integers.
std::string stages_to_string(const std::vector<int>& stages);
std::optional<std::vector<int>> parse_stages(std::string_view text);

}  // namespace sgmp::engine
