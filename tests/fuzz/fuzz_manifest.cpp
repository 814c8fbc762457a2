// libFuzzer target: the cross-validation manifest reader.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "sgmp/compare/manifest.hpp"
#include "sgmp/pack/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        (void)sgmp::compare::read_manifest(in, "fuzz.csv");
    } catch (const sgmp::InputError&) {
    }
    return 0;
}
