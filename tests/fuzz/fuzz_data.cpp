// libFuzzer target: the LAMMPS data reader, blends (per-atom `# bin B species S`) included.
// What it accepts must convert: written as extended XYZ (as `sgmp convert` does), it reads
// back with the same particles (reliability finding 11: an atom of a blend without its tag
// was written as species_id 0, which the extended XYZ reader refuses).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/lammps_data_format.hpp"
#include "sgmp/pack/xyz_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    sgmp::Pack pack;
    try {
        pack = sgmp::read_lammps_data(in, "fuzz.data");
    } catch (const sgmp::InputError&) {
        return 0;
    }
    std::ostringstream xyz;
    try {
        sgmp::write_xyz(xyz, pack);
    } catch (const std::invalid_argument&) {
        return 0;  // a value the writer refuses in one line (a quote, a container it rejects)
    }
    std::istringstream back(xyz.str());
    try {
        const sgmp::Pack again = sgmp::read_xyz(back, "fuzz.xyz");
        if (again.particles.size() != pack.particles.size()) {
            std::abort();
        }
        for (std::size_t i = 0; i < pack.particles.size(); ++i) {
            if (again.particles[i].species != pack.particles[i].species ||
                again.particles[i].color != pack.particles[i].color ||
                again.particles[i].id != pack.particles[i].id) {
                std::abort();
            }
        }
    } catch (const sgmp::InputError&) {
        std::abort();  // `convert` would have written a file our own reader refuses
    }
    return 0;
}
