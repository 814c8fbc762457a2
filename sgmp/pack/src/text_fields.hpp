#pragma once
// Private helpers of the pack readers: numbered lines and strict field parsing.

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/line_reader.hpp"

namespace sgmp::detail {

using sgmp::LineReader;

/// Whitespace-separated fields of a line.
std::vector<std::string_view> split_fields(std::string_view line);
/// The same into `fields` (cleared first), whose memory a reader reuses line after line.
void split_fields(std::string_view line, std::vector<std::string_view>& fields);

/// Strict parses: the whole field must be the number. nullopt when it is not.
std::optional<double> parse_double(std::string_view field);
std::optional<std::int64_t> parse_integer(std::string_view field);

/// Digits after the decimal point of a number's text, less its decimal exponent
/// ("0.125" 3, "1.5e-05" 6, "12" 0, "1e3" 0): the place of its last written digit.
int decimals_of(std::string_view field);

/// The one bin rule of the readers (extended XYZ `bin`, dump `bin`, data `# bin`): an
/// integer in [0, kMaxBin]. nullopt when `field` is not one (4294967297 is no bin 1).
inline constexpr std::int64_t kMaxBin = 1000000;
std::optional<int> parse_bin(std::string_view field);
/// "bin 'FIELD' is not an integer in [0, 1000000]": the rule's one wording.
std::string bin_error(std::string_view field);

/// The one header rule of the pack readers (extended XYZ header, LAMMPS data `# key=value`
/// comments): at most kMaxHeaderKeys keys, each once (a repeated key would leave which
/// value counts to chance), key and value free of control characters (they would reach
/// terminals raw: `sgmp-compare header`) and well-formed UTF-8 (they reach JSON outputs).
inline constexpr std::size_t kMaxHeaderKeys = 10000;
class HeaderKeys {
  public:
    /// Throws the reader's error at its current line when the entry breaks the rule.
    void add(const std::string& key, const std::string& value, const LineReader& reader);

  private:
    std::set<std::string> seen_;
};

/// True when the line has only blanks.
bool is_blank(std::string_view line);

/// The one size rule of the readers: a particle's size comes from a 'radius' or a
/// 'diameter' column, never both (which would count is not clear). `columns` names the
/// list ("Properties", "ATOMS section"); throws the reader's error at its current line.
void check_one_size_column(bool radius, bool diameter, const std::string& columns,
                           const LineReader& reader);

}  // namespace sgmp::detail

#include <unordered_map>

#include "sgmp/pack/particle.hpp"

namespace sgmp::detail {

/// Throws InputError(source, line) unless the particle's centre is finite and its radius
/// finite and > 0.
void check_particle_values(const Particle& particle, const std::string& source, std::size_t line);

/// Checks each particle as it is read: its values (check_particle_values) and an id not
/// seen before. Throws InputError at the line given (or the reader's current line).
class ParticleValidator {
  public:
    void check(const Particle& particle, const LineReader& reader);
    /// The id check alone, for particles whose values were checked already.
    void check_id(std::int64_t id, const std::string& source, std::size_t line);

  private:
    /// Line of each id seen, for ids in [0, size) (0: not seen). Ids of packs are nearly
    /// always 1…N, which this table holds in 8 bytes each, without a hash or allocation.
    std::vector<std::size_t> dense_line_;
    /// Lines of the ids the table does not hold.
    std::unordered_map<std::int64_t, std::size_t> sparse_line_;
    std::size_t seen_ = 0;
};

}  // namespace sgmp::detail

#include "sgmp/pack/pack.hpp"
#include "sgmp/pack/read_options.hpp"

namespace sgmp::detail {
/// Format readers on an already-open line reader (used after format detection).
PackRead read_xyz_lines(LineReader& reader, const ReadOptions& options);
Pack read_dump_lines(LineReader& reader);
}  // namespace sgmp::detail
