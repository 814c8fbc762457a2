#include "sgmp/batch/parameters.hpp"

#include <stdexcept>

#include "sgmp/engine/pack_parameters.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/size_modes.hpp"

namespace sgmp::batch {
namespace {

/// Every row of the pack parameter table but the seed (a sweep's seeds are its own axis).
std::vector<Parameter> make_parameters() {
    std::vector<Parameter> table;
    for (const engine::PackParameter& row : engine::pack_parameters()) {
        if (row.name == "seed") {
            continue;
        }
        const bool blank = row.required || row.unset_by_default;
        table.push_back({row.name, blank ? "" : row.default_text, row.kind == ValueKind::List});
    }
    return table;
}

}  // namespace

const std::vector<Parameter>& parameters() {
    static const std::vector<Parameter> table = make_parameters();
    return table;
}

std::size_t parameter_index(std::string_view name) {
    const auto& table = parameters();
    const Parameter* found = find_row(table, name);
    return found == nullptr ? std::string::npos : static_cast<std::size_t>(found - table.data());
}

engine::PackRequest to_request(const ParameterValues& values, std::uint64_t seed,
                               const DistributionFiles& files) {
    const auto& table = parameters();
    if (values.size() != table.size()) {
        throw std::invalid_argument("a job needs one value per parameter");
    }
    engine::PackRequest request;
    request.seed = seed;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const engine::PackParameter& row = *engine::find_pack_parameter(table[i].name);
        if (row.unset_by_default && values[i].empty()) {
            continue;
        }
        const auto file = files.find(values[i]);
        if (row.name == "size_distribution" && !sgmp::is_lognormal(values[i]) &&
            file != files.end()) {
            request.size_modes = sgmp::parse_size_distribution_csv(file->second, file->first);
            request.size_distribution = values[i];
            continue;
        }
        engine::set_pack_parameter(request, row.name, values[i]);
    }
    engine::validate(request);  // ParameterError, named as headers do: the front end spells it
    return request;
}

}  // namespace sgmp::batch
