#include "sgmp/batch/plan.hpp"

#include "sgmp/pack/parameter_error.hpp"

#include <algorithm>
#include <stdexcept>

namespace sgmp::batch {
namespace {

/// The value lists with defaults filled in; throws for an empty required list.
std::vector<std::vector<std::string>> filled(const Grid& grid) {
    const auto& table = parameters();
    if (grid.values.size() != table.size()) {
        throw std::invalid_argument("a grid needs one value list per parameter");
    }
    std::vector<std::vector<std::string>> lists = grid.values;
    for (std::size_t i = 0; i < table.size(); ++i) {
        auto& list = lists[i];
        if (list.empty()) {
            if (table[i].name == "count" || table[i].name == "arrangement") {
                throw ParameterError(table[i].name, "",
                                     "the grid is empty; give at least one value");
            }
            list.push_back(table[i].default_value);
        }
        std::vector<std::string> sorted = list;
        std::sort(sorted.begin(), sorted.end());
        const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
        if (repeated != sorted.end()) {
            throw ParameterError(table[i].name, *repeated, "is listed twice (each value once)");
        }
    }
    return lists;
}

}  // namespace

Plan make_plan(const Grid& grid) {
    const auto lists = filled(grid);
    if (grid.seeds.empty()) {
        throw ParameterError("seeds", "", "the grid is empty; give at least one seed");
    }
    std::uint64_t total = grid.seeds.size();
    for (const auto& list : lists) {
        if (total > kMaxJobs / list.size()) {
            throw std::invalid_argument("the grid holds more than " + std::to_string(kMaxJobs) +
                                        " jobs; split it into several batches");
        }
        total *= list.size();
    }
    Plan plan;
    plan.seeds = grid.seeds;
    plan.distribution_files = grid.distribution_files;
    for (const auto& list : lists) {
        plan.varies.push_back(list.size() > 1);
    }
    // Odometer over the lists, the last parameter fastest.
    std::vector<std::size_t> digit(lists.size(), 0);
    while (true) {
        ParameterValues values;
        values.reserve(lists.size());
        for (std::size_t i = 0; i < lists.size(); ++i) {
            values.push_back(lists[i][digit[i]]);
        }
        // Throws for an invalid combination.
        (void)to_request(values, grid.seeds.front(), grid.distribution_files);
        plan.combinations.push_back(std::move(values));
        std::size_t i = lists.size();
        while (i > 0 && ++digit[i - 1] == lists[i - 1].size()) {
            digit[i - 1] = 0;
            --i;
        }
        if (i == 0) {
            return plan;
        }
    }
}

}  // namespace sgmp::batch
