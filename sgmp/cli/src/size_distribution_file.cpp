#include "sgmp/cli/size_distribution_file.hpp"

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/bounded_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"

namespace sgmp::cli {

std::vector<SizeMode> read_size_distribution_file(const std::string& path,
                                                  std::string* largest_diameter) {
    if (!std::filesystem::is_regular_file(path)) {
        throw UsageError("--size-distribution " + path + ": must name a readable file");
    }
    try {
        const std::string text =
            read_bounded_file(path, kMaxSmallFileBytes, "a size distribution file");
        return parse_size_distribution_csv(text, path, largest_diameter);
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
