#include "sgmp/pack/input_error.hpp"

#include <cstdint>

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

bool is_utf8(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
        const auto byte = static_cast<unsigned char>(text[i]);
        std::size_t length = 0;
        std::uint32_t code = 0;
        if (byte < 0x80) {
            ++i;
            continue;
        } else if (byte >= 0xc2 && byte <= 0xdf) {
            length = 2;
            code = byte & 0x1fu;
        } else if (byte >= 0xe0 && byte <= 0xef) {
            length = 3;
            code = byte & 0x0fu;
        } else if (byte >= 0xf0 && byte <= 0xf4) {
            length = 4;
            code = byte & 0x07u;
        } else {
            return false;  // a continuation byte alone, 0xc0, 0xc1 or 0xf5 and above
        }
        if (i + length > text.size()) {
            return false;
        }
        for (std::size_t k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + k]);
            if ((next & 0xc0u) != 0x80u) {
                return false;
            }
            code = (code << 6) | (next & 0x3fu);
        }
        const std::uint32_t smallest = length == 2 ? 0x80u : length == 3 ? 0x800u : 0x10000u;
        if (code < smallest || code > 0x10ffffu || (code >= 0xd800u && code <= 0xdfffu)) {
            return false;
        }
        i += length;
    }
    return true;
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
