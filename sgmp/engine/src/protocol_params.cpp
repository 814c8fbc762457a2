#include "sgmp/engine/protocol_params.hpp"

#include <charconv>
#include <cmath>

#include "sgmp/pack/parameter_error.hpp"

namespace sgmp::engine {

void validate(const ProtocolParams& p, double diameter) {
    if (!(p.circle_factor > 1.0) || !std::isfinite(p.circle_factor)) {
        throw ParameterError("circle_factor", format_number(p.circle_factor),
                             "must be a number greater than 1 (sweep radius = d / factor)");
    }
    if (p.sweep_stages.empty()) {
        throw ParameterError("sweep_stages", "", "needs at least one stage");
    }
    for (std::size_t i = 0; i < p.sweep_stages.size(); ++i) {
        const int n = p.sweep_stages[i];
        if (n < 3 || n > kMaxSweepPositions) {
            throw ParameterError(p.sweep_stages.size() == 1 ? "sweep_positions" : "sweep_stages",
                                 stages_to_string(p.sweep_stages),
                                 "every stage needs 3 to 1000000 sweep positions");
        }
        if (i > 0 && n <= p.sweep_stages[i - 1]) {
            throw ParameterError("sweep_stages", stages_to_string(p.sweep_stages),
                                 "stages must have strictly increasing position counts");
        }
    }
    if (p.lower_neighbours < 1) {
        throw ParameterError("lower_neighbours", std::to_string(p.lower_neighbours),
                             "must be at least 1");
    }
    // The step fall needs a step below the smallest diameter; the exact fall ignores it.
    if (!(p.fall_step > 0.0) || !std::isfinite(p.fall_step) ||
        (p.fall == FallMode::Step && !(p.fall_step < diameter))) {
        throw ParameterError(
            "fall_step", format_number(p.fall_step),
            "must be greater than 0 and less than the diameter " + format_number(diameter));
    }
    if (!(p.momentum >= 0.0) || !(p.momentum < 1.0)) {
        throw ParameterError("momentum", format_number(p.momentum), "must be in [0, 1)");
    }
    if (p.stall_moves < 1) {
        throw ParameterError("stall_moves", std::to_string(p.stall_moves), "must be at least 1");
    }
    if (p.max_moves < 1) {
        throw ParameterError("max_moves", std::to_string(p.max_moves), "must be at least 1");
    }
}

const NameTable<FallMode, 2>& fall_modes() {
    static constexpr NameTable<FallMode, 2> table{
        {{{FallMode::Exact, "exact"}, {FallMode::Step, "step"}}}};
    return table;
}
const NameTable<GapRule, 2>& gap_rules() {
    static constexpr NameTable<GapRule, 2> table{
        {{{GapRule::Largest, "largest"}, {GapRule::Random, "random"}}}};
    return table;
}
const NameTable<ContactModel, 3>& contact_models() {
    static constexpr NameTable<ContactModel, 3> table{{{{ContactModel::None, "none"},
                                                        {ContactModel::Settle, "settle"},
                                                        {ContactModel::Roll, "roll"}}}};
    return table;
}
const NameTable<WallRule, 2>& wall_rules() {
    static constexpr NameTable<WallRule, 2> table{
        {{{WallRule::Fix, "fix"}, {WallRule::Block, "block"}}}};
    return table;
}

std::string_view to_string(FallMode mode) {
    return fall_modes().name(mode);
}
std::string_view to_string(GapRule rule) {
    return gap_rules().name(rule);
}
std::string_view to_string(ContactModel model) {
    return contact_models().name(model);
}
std::string_view to_string(WallRule rule) {
    return wall_rules().name(rule);
}
std::optional<FallMode> parse_fall_mode(std::string_view text) {
    return fall_modes().parse(text);
}
std::optional<GapRule> parse_gap_rule(std::string_view text) {
    return gap_rules().parse(text);
}
std::optional<ContactModel> parse_contact_model(std::string_view text) {
    return contact_models().parse(text);
}
std::optional<WallRule> parse_wall_rule(std::string_view text) {
    return wall_rules().parse(text);
}

std::string stages_to_string(const std::vector<int>& stages) {
    std::string text;
    for (const int n : stages) {
        text += (text.empty() ? "" : ",") + std::to_string(n);
    }
    return text;
}

std::optional<std::vector<int>> parse_stages(std::string_view text) {
    std::vector<int> stages;
    while (true) {
        const std::size_t comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        int n = 0;
        const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), n);
        if (item.empty() || error != std::errc() || end != item.data() + item.size()) {
            return std::nullopt;
        }
        stages.push_back(n);
        if (comma == std::string_view::npos) {
            return stages;
        }
        text.remove_prefix(comma + 1);
    }
}

void record(const ProtocolParams& p, Metadata& m) {
    m.set_number("circle_factor", p.circle_factor);
    m.set("sweep_stages", stages_to_string(p.sweep_stages));
    m.set_integer("lower_neighbours", p.lower_neighbours);
    m.set("gap", std::string(to_string(p.gap)));
    m.set("fall", std::string(to_string(p.fall)));
    m.set_number("fall_step", p.fall_step);
    m.set("contact", std::string(to_string(p.contact)));
    m.set_number("momentum", p.momentum);
    m.set("walls", std::string(to_string(p.walls)));
    m.set_integer("stall_moves", p.stall_moves);
    m.set_integer("max_moves", p.max_moves);
}

}  // namespace sgmp::engine
