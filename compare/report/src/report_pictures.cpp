#include "sgmp/report/report_pictures.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "sgmp/metrics/measure.hpp"
#include "sgmp/metrics/sphere_values.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/render/povray.hpp"
#include "sgmp/render/scene.hpp"

namespace sgmp::report {
namespace fs = std::filesystem;
namespace {

std::string slug(const std::string& text) {
    std::string out;
    for (const char c : text) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.';
        if (keep) {
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        } else if (!out.empty() && out.back() != '-') {
            out += '-';
        }
    }
    while (!out.empty() && out.back() == '-') {
        out.pop_back();
    }
    return out;
}

std::size_t pictured_count(const std::vector<ManifestEntry>& manifest, std::size_t preferred) {
    std::set<std::size_t> candidates;
    std::set<std::size_t> references;
    for (const auto& e : manifest) {
        if (e.role == Role::Candidate || e.role == Role::Reference) {
            (e.role == Role::Candidate ? candidates : references).insert(e.count);
        }
    }
    std::size_t best = 0;
    for (const std::size_t n : candidates) {
        if (references.contains(n)) {
            if (n == preferred) {
                return n;
            }
            best = std::max(best, n);
        }
    }
    return best;
}

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

/// Gap tolerance of the pictures' coordination, over the mean diameter (the report's Z(10⁻³)).
constexpr double kPictureContactGap = 1e-3;
/// The colour scale's top is the largest Z pictured, never below 6 (a frictionless packing's
/// isostatic count), so that SGMP's Z near 3 reads as low against DEM's 5–6.
constexpr double kLeastTopOfScale = 6.0;

std::string caption(const PictureChoice& c) {
    return (c.reference ? "" : "SGMP ") + c.group + ", seed " + std::to_string(c.seed);
}

}  // namespace

std::vector<PictureChoice> choose_pictures(const std::vector<ManifestEntry>& manifest,
                                           std::size_t preferred) {
    const std::size_t count = pictured_count(manifest, preferred);
    std::vector<PictureChoice> choices;
    if (count == 0) {
        return choices;
    }
    for (const bool reference : {false, true}) {
        std::vector<std::string> order;
        std::map<std::string, const ManifestEntry*> lowest;
        for (const auto& e : manifest) {
            const bool is_reference = e.role == Role::Reference;
            const bool pictured = e.role == Role::Candidate || e.role == Role::Reference;
            if (e.count != count || !pictured || is_reference != reference) {
                continue;
            }
            auto [it, fresh] = lowest.emplace(e.group, &e);
            if (fresh) {
                order.push_back(e.group);
            } else if (e.seed < it->second->seed) {
                it->second = &e;
            }
        }
        for (const auto& group : order) {
            const ManifestEntry& e = *lowest[group];
            PictureChoice c{group, reference, count, e.seed, e.path, "", std::nullopt};
            c.file = "pictures/n" + std::to_string(count) + "-" + (reference ? "r" : "c") +
                     std::to_string(choices.size() + 1) + "-" + slug(group) + ".png";
            choices.push_back(c);
        }
    }
    return choices;
}

PictureSet render_pictures(const std::vector<PictureChoice>& choices, int size) {
    PictureSet set;
    const auto povray = render::find_povray();
    if (!povray) {
        set.note = render::povray_missing_note();
        return set;
    }
    if (choices.empty()) {
        set.note = "no particle count has both candidate and reference packs to picture";
        return set;
    }
    const auto start = std::chrono::steady_clock::now();
    render::SceneOptions options;
    options.width = size;
    options.height = size;
    options.view = render::View{35.0, 30.0};
    options.cut = *render::parse_cut("half");
    // Coloured by coordination, the gap between SGMP and DEM that matters (Z(10⁻³)), on one
    // scale for every picture: 0 to the largest Z pictured (at least 6).
    options.coloring = render::Coloring::Values;
    options.caption = {"Z", "gap <= 1e-3 d"};
    options.key_text = render::key_font_found();
    std::string scratch_name = (fs::temp_directory_path() / "sgmp-pictures-XXXXXX").string();
    if (::mkdtemp(scratch_name.data()) == nullptr) {
        set.note = "pictures skipped: cannot create a scratch directory";
        return set;
    }
    const fs::path scratch(scratch_name);
    try {
        std::vector<Pack> packs;
        std::vector<std::vector<double>> coordination;
        double z_top = kLeastTopOfScale;
        for (const auto& c : choices) {
            ReadOptions read;
            read.container = c.container;
            packs.push_back(read_pack_file(c.path, read).pack);
            coordination.push_back(metrics::sphere_contact_numbers(
                packs.back().particles, metrics::container_of(packs.back()), kPictureContactGap));
            for (const double z : coordination.back()) {
                z_top = std::max(z_top, z);
            }
        }
        options.value_limits = std::pair{0.0, z_top};
        for (std::size_t i = 0; i < choices.size(); ++i) {
            const PictureChoice& c = choices[i];
            options.provenance = "pack: " + c.path;
            options.values = coordination[i];
            render::RenderJob job;
            job.scene = render::povray_scene(packs[i], options);
            job.width = size;
            job.height = size;
            job.out = scratch / "picture.png";
            job.overwrite = true;
            job.texts = {{"Software", "sgmp-compare crossval " + std::string(sgmp::version())},
                         {"Source", c.path},
                         {"Comment", caption(c) +
                                         "; view 35,30; half cut away; coloured by coordination "
                                         "Z (gap <= 1e-3 d), 0 to " +
                                         std::to_string(static_cast<int>(z_top))}};
            render::render_png(*povray, job);
            set.files.emplace_back(c.file, read_bytes(job.out));
        }
        set.made = true;
    } catch (const std::exception& error) {
        set.files.clear();
        set.note = std::string("pictures skipped: ") + error.what();
    }
    std::error_code ignored;
    fs::remove_all(scratch, ignored);
    set.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return set;
}

std::string pictures_markdown(const std::vector<PictureChoice>& choices, const PictureSet& set) {
    std::ostringstream md;
    md << "\n## Pictures\n\n";  // a blank line ends whatever came before
    if (!set.made) {
        md << "No pictures: " << set.note << ".\n\n";
        return md.str();
    }
    md << "One pack of each SGMP mode beside one DEM pour of each friction class at N = "
       << choices.front().count
       << ", seen from azimuth 35°, elevation 30°, with the half nearer the camera cut away "
          "(spheres whose centre lies in front of the vertical plane through the container's "
          "axis are not drawn), so the cut face shows the inside; spheres coloured by their "
          "coordination Z, the spheres within 10⁻³·d of them (viridis on one scale for every "
          "picture, from 0 to the largest Z pictured: dark for few contacts, yellow for many; "
          "the key on the right), the container outlined up to the top. Rendered with "
          "POV-Ray; each picture opens at full size.\n\n";
    // At most kPerRow pictures a table, so that the page fits 1400 px (nine side by side
    // took 1715 px).
    constexpr std::size_t kPerRow = 5;
    for (std::size_t first = 0; first < choices.size(); first += kPerRow) {
        const std::size_t last = std::min(choices.size(), first + kPerRow);
        md << "|";
        for (std::size_t i = first; i < last; ++i) {
            md << " " << caption(choices[i]) << " |";
        }
        md << "\n|";
        for (std::size_t i = first; i < last; ++i) {
            md << " --- |";
        }
        md << "\n|";
        for (std::size_t i = first; i < last; ++i) {
            const auto& c = choices[i];
            md << " [![" << caption(c) << "](" << c.file << ")](" << c.file << ") |";
        }
        md << "\n\n";
    }
    return md.str();
}

}  // namespace sgmp::report
