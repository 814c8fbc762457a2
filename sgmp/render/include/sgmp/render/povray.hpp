#pragma once
/// @file povray.hpp
/// Running POV-Ray on a scene text to make a PNG, written atomically: POV-Ray renders into
/// a scratch directory (its file-access rules allow writing only under the working
/// directory), the image gets its provenance text chunks and is renamed into place.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sgmp::render {

/// The POV-Ray executable: $SGMP_POVRAY when set (empty: none), else `povray` on PATH.
std::optional<std::filesystem::path> find_povray();

/// Whether the key's font, POV-Ray's `cyrvetic.ttf` (Debian povray-includes), is in one of
/// POV-Ray's usual include folders (/usr/share/povray-3.7/include, /usr/local/share/…); a
/// picture whose key would need it otherwise gets a key without labels.
bool key_font_found();

/// One line saying why there are no pictures, for when find_povray() finds nothing.
std::string povray_missing_note();

struct RenderJob {
    std::string scene;
    int width = 800;
    int height = 800;
    std::filesystem::path out;
    bool overwrite = false;
    /// tEXt chunks recorded in the PNG (png_info.hpp).
    std::vector<std::pair<std::string, std::string>> texts;
    /// POV-Ray's render threads (0: its default, every core).
    int threads = 0;
};

/// Renders `job` with `povray` and writes job.out. Throws std::runtime_error with a
/// one-line reason (POV-Ray's last error line) on failure; no file is left then.
void render_png(const std::filesystem::path& povray, const RenderJob& job);

}  // namespace sgmp::render
