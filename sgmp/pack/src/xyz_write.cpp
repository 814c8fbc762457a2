// The extended XYZ writer (xyz_format.hpp): the comment line (Properties, Lattice, Origin,
// pbc, the container and the pack's metadata) and the particle lines, formatted in blocks.
#include <charconv>
#include <ostream>

#include "sgmp/pack/header_entry.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/particle_density.hpp"
#include "sgmp/pack/xyz_format.hpp"
#include "xyz_internal.hpp"

namespace sgmp {
namespace {

constexpr std::string_view kProperties = "id:I:1:pos:R:3:radius:R:1:bin:I:1";
/// The species of a blend (particle.hpp). Not `species`: in extended XYZ that is the
/// chemical-symbol column (ASE reads it as element symbols and fails on numbers).
constexpr std::string_view kSpeciesProperty = ":species_id:I:1";
/// ASE reads (and writes) the `masses` column as the atoms' masses.
constexpr std::string_view kMassProperty = ":masses:R:1";

bool needs_quotes(const std::string& value) {
    return value.empty() || value.find_first_of(" \t=") != std::string::npos;
}

std::string lattice_text(const Box& box) {
    const Vec3 side = box.hi - box.lo;
    return format_number(side.x()) + " 0 0 0 " + format_number(side.y()) + " 0 0 0 " +
           format_number(side.z());
}

/// The `pbc` of a pack: periodic sides are x and z, or x and y when written z up.
std::string pbc_text(const Pack& pack) {
    const auto axes = periodic_axes(pack);
    std::string text;
    for (const bool periodic : axes) {
        text += text.empty() ? "" : " ";
        text += periodic ? "T" : "F";
    }
    return text;
}

/// The cell written as Lattice and Origin: the container from the floor to the top (not
/// widened: a pack's own cell), or the output frame's box (output_frame.hpp).
Box written_xyz_box(const Pack& pack) {
    if (pack.metadata.contains("box") || pack.metadata.contains("periodic_y")) {
        return container_box(pack);
    }
    const Container c = container_of(pack);
    return c.box_up_to(top_of(pack, c));
}

/// Appends `value` to `line` as std::to_chars writes it (shortest round trip for doubles,
/// the same text as format_number).
template <class T>
char* append(char* line, char* end, T value) {
    return std::to_chars(line, end, value).ptr;
}

/// The particle lines "id x y z radius bin [species] [mass]", formatted into a block of memory
/// that is written whenever it fills: one stream call per block instead of eleven per particle.
void write_particle_lines(std::ostream& out, const std::vector<Particle>& particles, bool species,
                          const std::vector<double>* densities) {
    constexpr std::size_t kBlock = 1 << 16;
    constexpr std::size_t kLongestLine = 8 * 32;  // eight numbers of at most 24 characters each
    std::vector<char> block(kBlock + kLongestLine);
    char* const begin = block.data();
    char* const end = begin + block.size();
    char* at = begin;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        at = append(at, end, p.id);
        for (const double value : {p.center.x(), p.center.y(), p.center.z(), p.radius}) {
            *at++ = ' ';
            at = append(at, end, value);
        }
        *at++ = ' ';
        at = append(at, end, p.color);
        if (species) {
            *at++ = ' ';
            at = append(at, end, p.species);
        }
        if (densities != nullptr) {
            *at++ = ' ';
            at = append(at, end, sphere_mass((*densities)[i], p.radius));
        }
        *at++ = '\n';
        if (static_cast<std::size_t>(at - begin) >= kBlock) {
            out.write(begin, at - begin);
            at = begin;
        }
    }
    out.write(begin, at - begin);
}

}  // namespace

void write_xyz(std::ostream& out, const Pack& pack) {
    const Box box = written_xyz_box(pack);
    out << pack.particles.size() << '\n';
    const bool species = has_species(pack.particles);
    const auto densities = particle_densities(pack);  // a mass column where they are stated
    out << "Properties=" << kProperties << (species ? kSpeciesProperty : "")
        << (densities ? kMassProperty : "") << " Lattice=\"" << lattice_text(box) << "\" Origin=\""
        << format_number(box.lo.x()) << ' ' << format_number(box.lo.y()) << ' '
        << format_number(box.lo.z()) << "\" pbc=\"" << pbc_text(pack) << "\"";
    if (!pack.metadata.contains("container")) {  // the walls, always (stated_container.hpp)
        out << " container=\"" << container_of(pack).to_string() << '"';
    }
    for (const auto& [key, value] : pack.metadata.entries()) {
        if (detail::is_derived_xyz_key(key)) {
            continue;
        }
        check_header_entry(key, value);
        out << ' ' << key << '=';
        if (needs_quotes(value)) {
            out << '"' << value << '"';
        } else {
            out << value;
        }
    }
    out << '\n';
    write_particle_lines(out, pack.particles, species, densities ? &*densities : nullptr);
}

}  // namespace sgmp
