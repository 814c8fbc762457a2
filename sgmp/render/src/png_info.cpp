#include "sgmp/render/png_info.hpp"

#include <array>
#include <stdexcept>

namespace sgmp::render {
namespace {

constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);

std::uint32_t big_endian(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        value = (value << 8) | static_cast<unsigned char>(bytes[at + k]);
    }
    return value;
}

void put_big_endian(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) {
        out.push_back(static_cast<char>((value >> shift) & 0xff));
    }
}

std::string chunk(const std::string& type, const std::string& data) {
    std::string out;
    put_big_endian(out, static_cast<std::uint32_t>(data.size()));
    out += type;
    out += data;
    put_big_endian(out, crc32(type + data));
    return out;
}

bool is_png(const std::string& bytes) {
    return bytes.size() >= 33 && std::string_view(bytes).substr(0, 8) == kSignature &&
           bytes.compare(12, 4, "IHDR") == 0;
}

}  // namespace

std::optional<PngSize> png_size(const std::string& bytes) {
    if (!is_png(bytes)) {
        return std::nullopt;
    }
    return PngSize{big_endian(bytes, 16), big_endian(bytes, 20)};
}

std::uint32_t crc32(const std::string& bytes) {
    static const auto table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) {
                c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
            }
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFU;
    for (const char byte : bytes) {
        c = table[(c ^ static_cast<unsigned char>(byte)) & 0xffU] ^ (c >> 8);
    }
    return c ^ 0xFFFFFFFFU;
}

std::string with_text_chunks(const std::string& png,
                             const std::vector<std::pair<std::string, std::string>>& texts) {
    if (!is_png(png)) {
        throw std::invalid_argument("not a PNG image");
    }
    std::string out(png.substr(0, 8));
    std::size_t at = 8;
    bool first = true;
    while (at + 12 <= png.size()) {
        const std::size_t length = big_endian(png, at);
        if (at + 12 + length > png.size()) {
            throw std::invalid_argument("a PNG chunk runs past the end of the image");
        }
        const std::string type = png.substr(at + 4, 4);
        if (type != "tIME") {
            out += png.substr(at, 12 + length);
        }
        if (first) {
            for (const auto& [keyword, text] : texts) {
                if (keyword.empty() || keyword.size() > 79) {
                    throw std::invalid_argument("a PNG text keyword must have 1 to 79 characters");
                }
                out += chunk("tEXt", keyword + std::string(1, '\0') + text);
            }
            first = false;
        }
        at += 12 + length;
    }
    return out;
}

}  // namespace sgmp::render
