// libFuzzer target: the regression baseline reader (JSON, then its entries).
#include <cstddef>
#include <cstdint>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/baseline.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto json = nlohmann::json::parse(data, data + size, nullptr, false);
    if (json.is_discarded()) {
        return 0;  // not JSON: the caller reports that before parse_baseline
    }
    try {
        (void)sgmp::report::parse_baseline(json, "fuzz.json");
    } catch (const sgmp::InputError&) {
    }
    return 0;
}
