// libFuzzer target: the rows of an `sgmp batch --measure` summary.csv read back by
// `crossval`/`report --metrics` (summaries_from_batch), then the physical-range check every
// judged pack passes (check_physical).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/report/agreement.hpp"
#include "sgmp/report/precomputed.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        for (const auto& [path, summary] : sgmp::report::summaries_from_batch(text, "fuzz.csv")) {
            sgmp::report::check_physical(summary);
        }
    } catch (const sgmp::InputError&) {
    } catch (const std::invalid_argument&) {  // check_physical's refusal
    }
    return 0;
}
