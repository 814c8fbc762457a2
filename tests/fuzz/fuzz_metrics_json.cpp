// libFuzzer target: the `measure` outputs read back by `crossval`/`report --metrics`
// (precomputed.hpp): NAME.metrics.json, NAME.g_r.csv and NAME.phi_y.csv, given as one input
// in three parts separated by NUL bytes, then the physical-range check every judged pack
// passes (check_physical). The measurement parameters are the file's own, so that inputs
// get past that comparison to the fields behind it.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/agreement.hpp"
#include "sgmp/report/precomputed.hpp"

namespace {

/// The part of `rest` up to the next NUL (all of it when there is none); `rest` moves past it.
std::string_view next_part(std::string_view& rest) {
    const auto end = rest.find('\0');
    const std::string_view part = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    return part;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view rest(reinterpret_cast<const char*>(data), size);
    const std::string_view json_text = next_part(rest);
    const std::string_view g_r = next_part(rest);
    const std::string_view phi_y = next_part(rest);
    const auto json = nlohmann::ordered_json::parse(json_text, nullptr, false);
    if (json.is_discarded()) {
        return 0;  // not JSON: the caller reports that before summary_from_measure
    }
    nlohmann::ordered_json parameters;
    if (json.is_object() && json.contains("provenance") && json["provenance"].is_object()) {
        parameters = json["provenance"].value("parameters", nlohmann::ordered_json());
    }
    try {
        const auto summary =
            sgmp::report::summary_from_measure("fuzz.metrics.json", json, g_r, phi_y, parameters);
        sgmp::report::check_physical(summary);
    } catch (const sgmp::InputError&) {
    } catch (const std::invalid_argument&) {  // check_physical's refusal
    }
    return 0;
}
