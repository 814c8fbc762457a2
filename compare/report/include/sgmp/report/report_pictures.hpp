#pragma once
/// @file report_pictures.hpp
/// Pictures of packs in the cross-validation report: at N = 9000 (or the largest count
/// with both candidate and reference packs) one seed of each candidate group (SGMP mode)
/// beside one pour of each reference group (DEM friction class), rendered with POV-Ray
/// (sgmp_render) cut away so the inside shows. Missing POV-Ray is a one-line note, not an
/// error.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sgmp/pack/stated_container.hpp"
#include "sgmp/report/manifest.hpp"

namespace sgmp::report {

/// The count pictured by default.
inline constexpr std::size_t kPictureCount = 9000;

struct PictureChoice {
    std::string group;
    bool reference = false;
    std::size_t count = 0;
    std::uint64_t seed = 0;
    std::string path;  ///< the pack file
    std::string
        file;  ///< the picture's name in the report, e.g. pictures/n9000-c1-loose-random.png
    /// The walls stated for the pack (the manifest's column or --container), if any.
    std::optional<StatedContainer> container{};
};

/// The packs pictured: at `preferred` when both roles have packs there, else at the largest
/// such count; per group (candidates in manifest order, then references) its lowest seed.
/// Variants are not pictured. Empty when no count has both roles.
std::vector<PictureChoice> choose_pictures(const std::vector<ManifestEntry>& manifest,
                                           std::size_t preferred = kPictureCount);

struct PictureSet {
    bool made = false;
    std::string note;                                        ///< why not, when not made
    std::vector<std::pair<std::string, std::string>> files;  ///< (name, PNG bytes)
    double seconds = 0.0;
};

/// Renders every choice (size × size pixels, view azimuth 35°, elevation 30°, the half
/// nearer the camera cut away, spheres coloured by colour bin) with POV-Ray. Without
/// POV-Ray, or when a render fails, returns made = false and a one-line note.
PictureSet render_pictures(const std::vector<PictureChoice>& choices, int size);

/// The report's "Pictures" section: one table row of captions and one of images (linked
/// to the full-size files), or the note in one line.
std::string pictures_markdown(const std::vector<PictureChoice>& choices, const PictureSet& set);

}  // namespace sgmp::report
