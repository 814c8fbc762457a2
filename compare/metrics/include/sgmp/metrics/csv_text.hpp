#pragma once
/// @file csv_text.hpp
/// The one layout of every CSV table sgmp-compare writes: the header row first, then `#`
/// lines saying what made the file (tool and version, command, rules or provenance), then
/// the rows. numpy.genfromtxt(path, comments='#', names=True, delimiter=','),
/// pandas.read_csv(path, comment='#') and ParaView's CSV reader (comment character `#`)
/// read it as it is. A field holding a comma, a quote or a line break is quoted (RFC 4180).

#include <ostream>
#include <string>
#include <vector>

#include "sgmp/pack/csv_fields.hpp"  // csv_field, the quoting

namespace sgmp::metrics {

/// `# tool: TOOL VERSION`, `# command: COMMAND`, then one `# rule: …` line per rule.
void write_csv_preamble(std::ostream& out, const std::string& tool, const std::string& command,
                        const std::vector<std::string>& rules);

}  // namespace sgmp::metrics
