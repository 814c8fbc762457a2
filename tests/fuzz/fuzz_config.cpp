// libFuzzer target: the `sgmp --config` file reader (CLI11's TOML reader and our mapping
// of its items to options).
#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "config_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        (void)sgmp::app::config_arguments(in, "pack");
    } catch (const std::invalid_argument&) {
    } catch (const CLI::ParseError&) {
    }
    return 0;
}
