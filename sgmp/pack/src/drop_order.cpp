#include "sgmp/pack/drop_order.hpp"

#include <numeric>

namespace sgmp {

const NameTable<DropOrder, 2>& drop_orders() {
    static constexpr NameTable<DropOrder, 2> table{
        {{{DropOrder::Stratified, "stratified"}, {DropOrder::Shuffled, "shuffled"}}}};
    return table;
}

std::string_view to_string(DropOrder order) {
    return drop_orders().name(order);
}

std::optional<DropOrder> parse_drop_order(std::string_view text) {
    return drop_orders().parse(text);
}

std::vector<std::size_t> stratified_sequence(const std::vector<std::size_t>& counts) {
    const std::size_t total = std::accumulate(counts.begin(), counts.end(), std::size_t{0});
    std::vector<std::size_t> placed(counts.size(), 0);
    std::vector<std::size_t> sequence;
    sequence.reserve(total);
    for (std::size_t k = 1; k <= total; ++k) {
        // Deficit k·nᵢ/N − pᵢ, compared as k·nᵢ − pᵢ·N (exact in long double below 2³²).
        std::size_t best = counts.size();
        long double best_deficit = 0.0L;
        for (std::size_t i = 0; i < counts.size(); ++i) {
            if (placed[i] == counts[i]) {
                continue;
            }
            const long double deficit = static_cast<long double>(k) * counts[i] -
                                        static_cast<long double>(placed[i]) * total;
            if (best == counts.size() || deficit > best_deficit) {
                best = i;
                best_deficit = deficit;
            }
        }
        ++placed[best];
        sequence.push_back(best);
    }
    return sequence;
}

}  // namespace sgmp
