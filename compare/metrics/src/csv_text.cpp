#include "sgmp/metrics/csv_text.hpp"

#include "sgmp/pack/version.hpp"

namespace sgmp::metrics {

void write_csv_preamble(std::ostream& out, const std::string& tool, const std::string& command,
                        const std::vector<std::string>& rules) {
    out << "# tool: " << tool << ' ' << sgmp::version() << '\n';
    out << "# command: " << command << '\n';
    for (const auto& rule : rules) {
        out << "# rule: " << rule << '\n';
    }
}

}  // namespace sgmp::metrics
