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
        // Every key taken for an option, none typed on the command line: the reader's
        // whole path runs for any input.
        (void)sgmp::app::config_arguments(
            in, "pack", [](const std::string&) { return true; },
            [](const std::string&) { return false; });
    } catch (const std::invalid_argument&) {
    } catch (const CLI::ParseError&) {
    }
    return 0;
}
