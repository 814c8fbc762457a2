#include "sgmp/cli/size_distribution_file.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp::cli {

std::vector<SizeMode> read_size_distribution_file(const std::string& path,
                                                  std::string* largest_diameter) {
    std::ifstream in(path, std::ios::binary);
    if (!std::filesystem::is_regular_file(path) || !in) {
        throw UsageError("--size-distribution " + path + ": must name a readable file");
    }
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return parse_size_distribution_csv(text.str(), path, largest_diameter);
    } catch (const InputError& e) {  // a bad input file: exit 1 (docs/command-line.md)
        throw std::runtime_error(std::string("--size-distribution ") + e.what());
    }
}

void warn_unnormalised(const std::string& program, const std::string& option,
                       const std::vector<SizeMode>& modes) {
    if (const auto total = unnormalised_total(modes)) {
        std::cerr << program << ": warning: " << printable(option) << ": fractions sum to "
                  << format_number(*total) << "; normalised to 1\n";
    }
}

}  // namespace sgmp::cli
