// libFuzzer target: the LAMMPS/LIGGGHTS dump custom reader.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "sgmp/pack/dump_format.hpp"
#include "sgmp/pack/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        (void)sgmp::read_dump_custom(in, "fuzz.dump");
    } catch (const sgmp::InputError&) {
    }
    return 0;
}
