// libFuzzer target: the extended-XYZ reader. Any input must give a pack or an InputError.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/xyz_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        (void)sgmp::read_xyz(in, "fuzz.xyz");
    } catch (const sgmp::InputError&) {
    }
    return 0;
}
