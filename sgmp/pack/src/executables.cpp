#include "sgmp/pack/executables.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string_view>

namespace sgmp {

std::optional<std::filesystem::path> find_executable(const std::string& name) {
    const auto runnable = [](const std::filesystem::path& p) {
        std::error_code ec;
        return std::filesystem::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
    };
    // Absolute, so a caller may run it from another working directory (the pours run
    // inside their temporary directory).
    const auto absolute = [](const std::filesystem::path& p) {
        std::error_code ec;
        const auto a = std::filesystem::absolute(p, ec);
        return ec ? p : a;
    };
    if (name.find('/') != std::string::npos) {
        return runnable(name) ? std::optional<std::filesystem::path>(absolute(name)) : std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::string_view dirs = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
    while (true) {
        const std::size_t colon = dirs.find(':');
        const std::string_view dir = dirs.substr(0, colon);
        const std::filesystem::path candidate =
            std::filesystem::path(dir.empty() ? "." : std::string(dir)) / name;
        if (runnable(candidate)) {
            return absolute(candidate);
        }
        if (colon == std::string_view::npos) {
            return std::nullopt;
        }
        dirs.remove_prefix(colon + 1);
    }
}

}  // namespace sgmp
