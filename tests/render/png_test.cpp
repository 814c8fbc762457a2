// PNG facts: the size from IHDR, CRC-32 against known values, text chunks inserted after
// IHDR with valid CRCs and time stamps removed.
#include <boost/test/unit_test.hpp>
#include <string>

#include "sgmp/render/png_info.hpp"

using namespace sgmp::render;

namespace {

std::string be32(std::uint32_t v) {
    return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
            static_cast<char>(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
    return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(crc32(type + data));
}

/// A PNG skeleton: signature, IHDR of w x h, a tIME chunk, an (empty) IDAT, IEND.
std::string skeleton(std::uint32_t w, std::uint32_t h) {
    return std::string("\x89PNG\r\n\x1a\n", 8) +
           chunk("IHDR", be32(w) + be32(h) + std::string("\x08\x02\x00\x00\x00", 5)) +
           chunk("tIME", std::string(7, '\x01')) + chunk("IDAT", "") + chunk("IEND", "");
}

}  // namespace

BOOST_AUTO_TEST_CASE(crc32_known_values) {
    BOOST_TEST(crc32("") == 0U);
    BOOST_TEST(crc32("123456789") == 0xCBF43926U);  // the standard check value
    BOOST_TEST(crc32("IEND") == 0xAE426082U);       // every PNG ends with these bytes
}

BOOST_AUTO_TEST_CASE(size_and_text_chunks) {
    const std::string png = skeleton(640, 480);
    BOOST_TEST(png_size(png)->width == 640U);
    BOOST_TEST(png_size(png)->height == 480U);
    BOOST_TEST(!png_size("not a png at all, certainly not one"));
    const std::string tagged = with_text_chunks(png, {{"Software", "sgmp render"}});
    const std::string text = chunk("tEXt", std::string("Software\0sgmp render", 20));
    const std::size_t after_ihdr = 8 + 25;
    BOOST_TEST(tagged.compare(after_ihdr, text.size(), text) == 0);
    BOOST_TEST(tagged.find("tIME") == std::string::npos);
    BOOST_TEST(png_size(tagged)->width == 640U);
    BOOST_CHECK_THROW(with_text_chunks(png, {{"", "x"}}), std::invalid_argument);
    BOOST_CHECK_THROW(with_text_chunks("nope", {}), std::invalid_argument);
}
