// libFuzzer target: both thesis table readers (results and starting packs).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/thesis_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::istringstream in(text);
        (void)sgmp::report::read_thesis_results(in, "results.csv");
    } catch (const sgmp::InputError&) {
    }
    try {
        std::istringstream in(text);
        (void)sgmp::report::read_thesis_starts(in, "starting_packs.csv");
    } catch (const sgmp::InputError&) {
    }
    return 0;
}
