#include "sgmp/pack/vtp_format.hpp"

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "sgmp/pack/pack_extent.hpp"

namespace sgmp {
namespace {

constexpr const char* kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

/// One appended array: its XML element (with the offset of its block) and its bytes.
class Appended {
  public:
    /// Adds `values` as a block; returns the `offset="…"` of its element.
    template <class T>
    std::string add(const std::vector<T>& values) {
        const std::string offset = "offset=\"" + std::to_string(bytes_.size()) + "\"";
        const std::uint64_t count = values.size() * sizeof(T);
        append(&count, sizeof count);
        append(values.data(), count);
        return offset;
    }
    [[nodiscard]] const std::string& bytes() const { return bytes_; }

  private:
    void append(const void* data, std::size_t size) {
        bytes_.append(static_cast<const char*>(data), size);
    }
    std::string bytes_;
};

/// The strings as VTK writes a String array in ASCII: each byte as a decimal number, each
/// string ended by 0.
std::string string_codes(const std::vector<std::string>& strings) {
    std::string out;
    for (const std::string& s : strings) {
        for (const char c : s) {
            out += std::to_string(static_cast<unsigned char>(c)) + ' ';
        }
        out += "0\n";
    }
    return out;
}

void write_head(std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\""
        << kByteOrder << "\" header_type=\"UInt64\">\n  <PolyData>\n";
}

}  // namespace

void write_vtp_particles(std::ostream& out, const Pack& pack) {
    const std::size_t n = pack.particles.size();
    std::vector<double> points;
    std::vector<double> radius;
    std::vector<std::int64_t> id;
    std::vector<std::int32_t> bin;
    std::vector<std::int32_t> species;
    std::vector<std::int64_t> connectivity(n);
    std::vector<std::int64_t> offsets(n);
    points.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Particle& p = pack.particles[i];
        points.insert(points.end(), {p.center.x(), p.center.y(), p.center.z()});
        radius.push_back(p.radius);
        id.push_back(p.id);
        bin.push_back(static_cast<std::int32_t>(p.color));
        species.push_back(static_cast<std::int32_t>(p.species));
        connectivity[i] = static_cast<std::int64_t>(i);
        offsets[i] = static_cast<std::int64_t>(i + 1);  // version 0.1: each vertex's end
    }
    std::vector<std::string> provenance;
    for (const auto& [key, value] : pack.metadata.entries()) {
        provenance.push_back(key + "=" + value);
    }
    Appended data;
    write_head(out);
    out << "    <FieldData>\n      <Array type=\"String\" Name=\"provenance\" NumberOfTuples=\""
        << provenance.size() << "\" format=\"ascii\">\n"
        << string_codes(provenance) << "      </Array>\n    </FieldData>\n";
    out << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
        << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "      <PointData Scalars=\"radius\">\n"
        << "        <DataArray type=\"Float64\" Name=\"radius\" format=\"appended\" "
        << data.add(radius) << "/>\n"
        << "        <DataArray type=\"Int64\" Name=\"id\" format=\"appended\" " << data.add(id)
        << "/>\n"
        << "        <DataArray type=\"Int32\" Name=\"bin\" format=\"appended\" " << data.add(bin)
        << "/>\n";
    if (has_species(pack.particles)) {
        out << "        <DataArray type=\"Int32\" Name=\"species\" format=\"appended\" "
            << data.add(species) << "/>\n";
    }
    out << "      </PointData>\n      <Points>\n"
        << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" "
        << data.add(points) << "/>\n      </Points>\n      <Verts>\n"
        << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" "
        << data.add(connectivity) << "/>\n"
        << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" "
        << data.add(offsets) << "/>\n      </Verts>\n    </Piece>\n  </PolyData>\n"
        << "  <AppendedData encoding=\"raw\">\n   _";
    out.write(data.bytes().data(), static_cast<std::streamsize>(data.bytes().size()));
    out << "\n  </AppendedData>\n</VTKFile>\n";
}

void write_vtp_container(std::ostream& out, const Pack& pack) {
    const Box box = container_box(pack);
    write_head(out);
    out << "    <Piece NumberOfPoints=\"8\" NumberOfVerts=\"0\" NumberOfLines=\"12\" "
           "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n      <Points>\n"
           "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (int corner = 0; corner < 8; ++corner) {
        out << "          " << format_number((corner & 1) ? box.hi.x() : box.lo.x()) << ' '
            << format_number((corner & 2) ? box.hi.y() : box.lo.y()) << ' '
            << format_number((corner & 4) ? box.hi.z() : box.lo.z()) << '\n';
    }
    out << "        </DataArray>\n      </Points>\n      <Lines>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    // The 12 edges join corners that differ in one bit.
    for (int corner = 0; corner < 8; ++corner) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if ((corner & bit) == 0) {
                out << "          " << corner << ' ' << (corner | bit) << '\n';
            }
        }
    }
    out << "        </DataArray>\n"
           "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n          ";
    for (int edge = 1; edge <= 12; ++edge) {
        out << 2 * edge << (edge < 12 ? ' ' : '\n');
    }
    out << "        </DataArray>\n      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

}  // namespace sgmp
