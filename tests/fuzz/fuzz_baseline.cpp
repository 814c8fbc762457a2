// libFuzzer target: the regression baseline reader as `sgmp-compare regress` runs it: the
// file's text parsed (parse_json_input: syntax and numbers beyond a double are one-line
// errors), then its entries (parse_baseline).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/baseline.hpp"
#include "sgmp/report/json_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto json = sgmp::report::parse_json_input(
            std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
        (void)sgmp::report::parse_baseline(json, "fuzz.json");
    } catch (const sgmp::InputError&) {
    }
    return 0;
}
