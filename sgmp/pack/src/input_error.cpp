#include "sgmp/pack/input_error.hpp"

namespace sgmp {

std::string printable(std::string_view text) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if ((byte >= 0x20 && byte < 0x7f) || byte == '\t') {
            out.push_back(c);
        } else {
            out += "\\x";
            out.push_back(kHex[byte >> 4]);
            out.push_back(kHex[byte & 0xf]);
        }
    }
    return out;
}

std::string excerpt(std::string_view text, std::size_t max) {
    if (text.size() <= max) {
        return std::string(text);
    }
    const std::size_t tail = max / 3;
    const std::size_t head = max - tail;
    return std::string(text.substr(0, head)) + " ... [" +
           std::to_string(text.size() - head - tail) + " bytes left out] ... " +
           std::string(text.substr(text.size() - tail));
}

namespace {
std::string compose(const std::string& source, std::size_t line, const std::string& reason) {
    const std::string cut = excerpt(reason, kMaxReasonBytes);
    if (line == 0) {
        return printable(excerpt(source, kMaxReasonBytes) + ": " + cut);
    }
    return printable(excerpt(source, kMaxReasonBytes) + ":" + std::to_string(line) + ": " + cut);
}
}  // namespace

InputError::InputError(const std::string& source, std::size_t line, const std::string& reason)
    : std::runtime_error(compose(source, line, reason)), source_(source), line_(line) {}

}  // namespace sgmp
