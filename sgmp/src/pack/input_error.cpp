#include "sgmp/pack/input_error.hpp"

namespace sgmp {

namespace {
std::string compose(const std::string& source, std::size_t line, const std::string& reason) {
    if (line == 0) {
        return source + ": " + reason;
    }
    return source + ":" + std::to_string(line) + ": " + reason;
}
}  // namespace

InputError::InputError(const std::string& source, std::size_t line, const std::string& reason)
    : std::runtime_error(compose(source, line, reason)), source_(source), line_(line) {}

}  // namespace sgmp
