#include <string>

#include "sgmp/pack/atom_types.hpp"
#include "sgmp/pack/dump_format.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/particle_density.hpp"
#include "text_fields.hpp"

namespace sgmp {

void write_dump_custom(std::ostream& out, const Pack& pack) {
    std::int64_t step = 0;
    if (const auto text = pack.metadata.get("timestep")) {
        step = detail::parse_integer(*text).value_or(0);
    }
    const AtomTypes types = atom_types(pack);
    const Box box = container_box(pack);
    out << "ITEM: TIMESTEP\n" << (step >= 0 ? step : 0) << '\n';
    out << "ITEM: NUMBER OF ATOMS\n" << pack.particles.size() << '\n';
    out << "ITEM: BOX BOUNDS";
    for (const bool periodic : periodic_axes(pack)) {  // LAMMPS' boundary flags
        out << (periodic ? " pp" : " ff");
    }
    // The walls, where the reader understands them (dump_format.cpp): not for a pack
    // written z up, which a dump (no header) reads back in the file's axes.
    if (pack.metadata.get("up_axis").value_or("y") != "z") {
        out << " container " << container_of(pack).to_string();
    }
    out << "\n";
    for (int k = 0; k < 3; ++k) {
        out << format_number(box.lo[k]) << ' ' << format_number(box.hi[k]) << '\n';
    }
    const bool species = has_species(pack.particles);
    // A mass column where the pack states densities (particle_density.hpp), in the file's units.
    const auto densities = particle_densities(pack);
    out << "ITEM: ATOMS id type x y z radius bin" << (species ? " species" : "")
        << (densities ? " mass" : "") << '\n';
    for (std::size_t i = 0; i < pack.particles.size(); ++i) {
        const Particle& p = pack.particles[i];
        out << p.id << ' ' << types.type[i] << ' ' << format_number(p.center.x()) << ' '
            << format_number(p.center.y()) << ' ' << format_number(p.center.z()) << ' '
            << format_number(p.radius) << ' ' << p.color;
        if (species) {
            out << ' ' << p.species;
        }
        if (densities) {
            out << ' ' << format_number(sphere_mass((*densities)[i], p.radius));
        }
        out << '\n';
    }
}

}  // namespace sgmp
