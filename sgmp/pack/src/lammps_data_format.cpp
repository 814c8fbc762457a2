#include "sgmp/pack/lammps_data_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "sgmp/pack/atom_types.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/particle_density.hpp"
#include "text_fields.hpp"

namespace sgmp {

void write_lammps_data(std::ostream& out, const Pack& pack) {
    for (const auto& p : pack.particles) {
        if (p.id <= 0) {
            throw std::invalid_argument("format data cannot carry id " + std::to_string(p.id) +
                                        ": LAMMPS atom ids must be positive");
        }
    }
    for (const auto& [key, value] : pack.metadata.entries()) {
        if (value.find_first_of("\n\r") != std::string::npos) {
            throw std::invalid_argument("format data cannot carry the value of '" + key +
                                        "': it holds a line break");
        }
    }
    const AtomTypes types = atom_types(pack);
    const Box box = container_box(pack);
    out << "LAMMPS data file (atom_style sphere) of a sphere pack\n";
    for (const auto& [key, value] : pack.metadata.entries()) {
        out << "# " << key << '=' << value << '\n';
    }
    // The density of each sphere (particle_density.hpp): LAMMPS' mass is density * (pi/6) * d^3.
    const auto stated = particle_densities(pack);
    const std::vector<double> density =
        stated.value_or(std::vector<double>(pack.particles.size(), kLammpsDataDensity));
    const std::string unit = pack.metadata.get("length_unit").value_or("control-volume sides");
    if (stated && densities_vary(*stated)) {
        out << "# density per species (size_modes): mass = density * (pi/6) * diameter^3, "
               "lengths in "
            << unit << '\n';
    } else {
        out << "# density " << format_number(density.empty() ? kLammpsDataDensity : density[0])
            << ": mass = density * (pi/6) * diameter^3, lengths in " << unit << '\n';
    }
    // LAMMPS' default neighbour skin is 0.3 (units lj) or 0.001 m (units si): many spheres
    // of a pack scaled to micrometres, so the neighbour lists overflow. A tenth of the
    // smallest diameter keeps them short.
    double smallest = 0.0;
    for (const Particle& p : pack.particles) {
        smallest = smallest == 0.0 ? 2.0 * p.radius : std::min(smallest, 2.0 * p.radius);
    }
    out << "# LAMMPS neighbor " << format_number(0.1 * smallest)
        << " bin: a skin of 0.1 * the smallest diameter (the default 0.3 of units lj, "
           "0.001 of units si, spans many spheres: \"Neighbor list overflow\")\n";
    out << "# LAMMPS boundary";
    for (const bool periodic : periodic_axes(pack)) {
        out << (periodic ? " p" : " f");
    }
    out << "\n\n";
    out << pack.particles.size() << " atoms\n" << types.count << " atom types\n\n";
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        out << format_number(box.lo[k]) << ' ' << format_number(box.hi[k]) << ' ' << axes[k]
            << "lo " << axes[k] << "hi\n";
    }
    out << "\nAtoms # sphere\n\n";
    const bool species = has_species(pack.particles);
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        const Particle& p = pack.particles[i];
        out << p.id << ' ' << types.type[i] << ' ' << format_number(2.0 * p.radius) << ' '
            << format_number(density[i]) << ' ' << format_number(p.center.x()) << ' '
            << format_number(p.center.y()) << ' ' << format_number(p.center.z()) << " # bin "
            << p.color;
        if (species) {
            out << " species " << p.species;
        }
        out << '\n';
    }
}

namespace {

bool is_key(std::string_view word) {
    if (word.empty() || !(std::isalpha(static_cast<unsigned char>(word[0])) || word[0] == '_')) {
        return false;
    }
    return std::all_of(word.begin(), word.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
}

/// Header line "numbers... words..." (comment removed): the words joined, the numbers kept.
struct HeaderLine {
    std::vector<double> numbers;
    std::string words;
};

HeaderLine split_header(std::string_view text) {
    HeaderLine line;
    for (const auto field : detail::split_fields(text)) {
        const auto number = detail::parse_double(field);
        if (number && line.words.empty()) {
            line.numbers.push_back(*number);
        } else {
            line.words += (line.words.empty() ? "" : " ") + std::string(field);
        }
    }
    return line;
}

std::string_view before_comment(std::string_view line) {
    return line.substr(0, line.find('#'));
}

Particle parse_atom(const std::string& line, const LineReader& reader) {
    const auto hash = line.find('#');
    const auto fields = detail::split_fields(before_comment(line));
    if (fields.size() != 7 && fields.size() != 10) {
        throw reader.error(
            "expected 'id type diameter density x y z' (and optionally 3 image "
            "flags), found " +
            std::to_string(fields.size()) + " fields");
    }
    Particle p;
    const auto id = detail::parse_integer(fields[0]);
    if (!id) {
        throw reader.error("atom id '" + std::string(fields[0]) + "' is not an integer");
    }
    p.id = *id;
    const auto number = [&](std::size_t i, const char* what) {
        const auto value = detail::parse_double(fields[i]);
        if (!value) {
            throw reader.error(std::string(what) + " '" + std::string(fields[i]) +
                               "' is not a number");
        }
        return *value;
    };
    p.radius = 0.5 * number(2, "diameter");
    for (int k = 0; k < 3; ++k) {
        p.center[k] = number(4 + static_cast<std::size_t>(k), "coordinate");
    }
    if (hash != std::string::npos) {
        const auto comment = detail::split_fields(std::string_view(line).substr(hash + 1));
        if (comment.size() >= 2 && comment[0] == "bin") {  // the readers' one bin rule
            const auto bin = detail::parse_bin(comment[1]);
            if (!bin) {
                throw reader.error(detail::bin_error(comment[1]));
            }
            p.color = *bin;
        }
        if (comment.size() == 4 && comment[2] == "species") {  // "# bin B species S"
            const auto species = detail::parse_integer(comment[3]);
            if (!species || *species < 1 || *species > kMaxSpecies) {
                throw reader.error("species '" + std::string(comment[3]) +
                                   "' is not an integer in [1, " + std::to_string(kMaxSpecies) +
                                   "]");
            }
            p.species = static_cast<int>(*species);
        }
    }
    return p;
}

}  // namespace

Pack read_lammps_data(std::istream& in, const std::string& source) {
    LineReader reader(in, source);
    std::string line;
    if (!reader.next(line)) {
        throw InputError(source, 0, "empty file: expected the title line of a data file");
    }
    Pack pack;
    std::optional<std::int64_t> count;
    std::array<std::optional<std::pair<double, double>>, 3> bounds;
    const std::array<std::string, 3> bound_words{"xlo xhi", "ylo yhi", "zlo zhi"};
    bool in_atoms = false;
    detail::HeaderKeys keys;  // the extended XYZ reader's header rule
    while (!in_atoms && reader.next(line)) {
        const std::string_view text = line;
        const auto first = text.find_first_not_of(" \t");
        if (first != std::string_view::npos && text[first] == '#') {
            const auto body = text.substr(first + 1);
            const auto start = body.find_first_not_of(" \t");
            const auto eq = body.find('=');
            if (start != std::string_view::npos && eq != std::string_view::npos &&
                is_key(body.substr(start, eq - start))) {
                const std::string key(body.substr(start, eq - start));
                std::string value(body.substr(eq + 1));
                keys.add(key, value, reader);
                pack.metadata.set(key, std::move(value));
            }
            continue;
        }
        const HeaderLine header = split_header(before_comment(text));
        if (header.words == "atoms" && header.numbers.size() == 1) {
            const double n = header.numbers[0];
            // Checked before the cast: a double beyond 2^62 has no int64 to become.
            if (!(n >= 0.0 && n <= 4.6e18) || n != std::floor(n)) {
                throw reader.error("the atom count must be a non-negative integer");
            }
            count = static_cast<std::int64_t>(n);
        }
        for (std::size_t k = 0; k < 3; ++k) {
            if (header.words == bound_words[k] && header.numbers.size() == 2) {
                bounds[k] = std::pair{header.numbers[0], header.numbers[1]};
            }
        }
        if (header.numbers.empty() && header.words == "Atoms") {
            const auto style = detail::split_fields(text.substr(text.find("Atoms") + 5));
            if (style.size() >= 2 && style[0] == "#" && style[1] != "sphere") {
                throw reader.error("Atoms section of atom_style '" + std::string(style[1]) +
                                   "'; only atom_style sphere is read");
            }
            in_atoms = true;
        }
    }
    if (!count) {
        throw InputError(source, 0, "data file lacks the 'N atoms' header line");
    }
    if (!in_atoms) {
        throw InputError(source, 0, "data file lacks the Atoms section");
    }
    pack.particles.reserve(static_cast<std::size_t>(std::min<std::int64_t>(*count, 1 << 16)));
    detail::ParticleValidator validator;
    // A blend tags every atom with its species (`# bin B species S`): one untagged atom
    // would be written as species 0, which no reader takes back.
    std::optional<std::pair<std::size_t, bool>> first_tag;  // line of the first atom, tagged?
    while (static_cast<std::int64_t>(pack.particles.size()) < *count) {
        if (!reader.next(line)) {
            throw reader.error("file ends after " + std::to_string(pack.particles.size()) + " of " +
                               std::to_string(*count) + " atom lines");
        }
        if (detail::is_blank(before_comment(line))) {
            continue;
        }
        pack.particles.push_back(parse_atom(line, reader));
        validator.check(pack.particles.back(), reader);
        const bool tagged = pack.particles.back().species > 0;
        if (!first_tag) {
            first_tag = std::pair{reader.line_number(), tagged};
        } else if (first_tag->second != tagged) {
            throw reader.error(
                "atom " + std::to_string(pack.particles.back().id) +
                (tagged ? " has a species tag and the atom of line "
                        : " lacks the species tag ('# bin B species S') of the atom of line ") +
                std::to_string(first_tag->first) + (tagged ? " has none" : "") +
                ": a blend tags every atom, a single size none");
        }
    }
    // The box is only recorded, for a file that states no walls: a simulation box is not a
    // container (stated_container.hpp); the walls come from a `# container=` comment, as
    // `sgmp convert` writes it (and then nothing is added, so our files read back as written).
    if (!pack.metadata.contains("container") && bounds[0] && bounds[1] && bounds[2]) {
        std::string box;
        for (std::size_t k = 0; k < 3; ++k) {
            box.append(k > 0 ? " " : "")
                .append(format_number(bounds[k]->first))
                .append(" ")
                .append(format_number(bounds[k]->second));
        }
        pack.metadata.set("data_box", box);
    }
    pack.metadata.set("source_format", "lammps data");
    return pack;
}

}  // namespace sgmp
