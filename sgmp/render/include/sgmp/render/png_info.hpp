#pragma once
/// @file png_info.hpp
/// The few facts about PNG files the renderer needs: the size from the IHDR chunk and
/// text chunks (tEXt) carrying provenance. Bytes in, bytes out.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sgmp::render {

struct PngSize {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

/// Width and height of a PNG (signature, then IHDR: big-endian at bytes 16–23); nullopt
/// when the bytes are not a PNG.
std::optional<PngSize> png_size(const std::string& bytes);

/// CRC-32 (ISO 3309, polynomial 0xEDB88320 reflected) as PNG chunks use it.
std::uint32_t crc32(const std::string& bytes);

/// The PNG with `texts` (keyword, text; Latin-1, keyword 1–79 characters) as tEXt chunks
/// right after IHDR, and any time stamp (tIME) removed, so the file records what made it
/// and not when. Throws std::invalid_argument when the bytes are not a PNG.
std::string with_text_chunks(const std::string& png,
                             const std::vector<std::pair<std::string, std::string>>& texts);

}  // namespace sgmp::render
