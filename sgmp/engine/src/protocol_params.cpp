#include "sgmp/engine/protocol_params.hpp"

#include <charconv>

#include "sgmp/engine/pack_parameters.hpp"

namespace sgmp::engine {

void validate(const ProtocolParams& p, double diameter) {
    PackRequest request;
    request.protocol = p;
    check_pack_parameters(request, "protocol", {diameter});
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

}  // namespace sgmp::engine
