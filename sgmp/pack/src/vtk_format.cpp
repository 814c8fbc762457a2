#include "sgmp/pack/vtk_format.hpp"

#include <array>
#include <cstdio>
#include <string>

#include "sgmp/pack/pack_extent.hpp"

namespace sgmp {
namespace {

/// A string as VTK's legacy writer encodes it: bytes outside '!'..'~', and '%', as %XX.
std::string encode(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte <= ' ' || byte > '~' || byte == '%') {
            char buffer[4];
            std::snprintf(buffer, sizeof buffer, "%%%02X", byte);
            out += buffer;
        } else {
            out += c;
        }
    }
    return out;
}

void write_preamble(std::ostream& out, const std::string& title) {
    out << "# vtk DataFile Version 3.0\n" << title << "\nASCII\nDATASET POLYDATA\n";
}

void write_point(std::ostream& out, const Vec3& p) {
    out << format_number(p.x()) << ' ' << format_number(p.y()) << ' ' << format_number(p.z())
        << '\n';
}

}  // namespace

void write_vtk_particles(std::ostream& out, const Pack& pack) {
    const std::size_t n = pack.particles.size();
    write_preamble(out,
                   "sphere pack: " + std::to_string(n) + " points with radius, id and bin arrays");
    out << "POINTS " << n << " double\n";
    for (const auto& p : pack.particles) {
        write_point(out, p.center);
    }
    out << "VERTICES " << n << ' ' << 2 * n << '\n';
    for (std::size_t i = 0; i < n; ++i) {
        out << "1 " << i << '\n';
    }
    const auto& entries = pack.metadata.entries();
    out << "FIELD FieldData 1\nprovenance 1 " << entries.size() << " string\n";
    for (const auto& [key, value] : entries) {
        out << encode(key + "=" + value) << '\n';
    }
    out << "POINT_DATA " << n << "\nSCALARS radius double 1\nLOOKUP_TABLE default\n";
    for (const auto& p : pack.particles) {
        out << format_number(p.radius) << '\n';
    }
    out << "SCALARS id vtktypeint64 1\nLOOKUP_TABLE default\n";
    for (const auto& p : pack.particles) {
        out << p.id << '\n';
    }
    out << "SCALARS bin int 1\nLOOKUP_TABLE default\n";
    for (const auto& p : pack.particles) {
        out << p.color << '\n';
    }
    if (has_species(pack.particles)) {
        out << "SCALARS species int 1\nLOOKUP_TABLE default\n";
        for (const auto& p : pack.particles) {
            out << p.species << '\n';
        }
    }
}

void write_vtk_container(std::ostream& out, const Pack& pack) {
    const Box box = container_box(pack);
    write_preamble(out, "container of a sphere pack: walls, floor and the top of the pack");
    out << "POINTS 8 double\n";
    for (int corner = 0; corner < 8; ++corner) {
        write_point(out, Vec3((corner & 1) ? box.hi.x() : box.lo.x(),
                              (corner & 2) ? box.hi.y() : box.lo.y(),
                              (corner & 4) ? box.hi.z() : box.lo.z()));
    }
    // The 12 edges join corners that differ in one bit.
    out << "LINES 12 36\n";
    for (int corner = 0; corner < 8; ++corner) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if ((corner & bit) == 0) {
                out << "2 " << corner << ' ' << (corner | bit) << '\n';
            }
        }
    }
}

}  // namespace sgmp
