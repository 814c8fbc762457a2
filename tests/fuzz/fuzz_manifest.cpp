// libFuzzer target: the cross-validation manifest reader, then the grouping `crossval`
// makes of its rows (plan_groups: roles, groups, counts and seeds, duplicate paths).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/crossval.hpp"
#include "sgmp/report/manifest.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const auto manifest = sgmp::report::read_manifest(in, "fuzz.csv");
        (void)sgmp::report::plan_groups(manifest);
    } catch (const sgmp::InputError&) {
    } catch (const std::invalid_argument&) {  // plan_groups' refusal
    }
    return 0;
}
