// sgmp render PACK --out pack.png [--size WxH] [--view AZ,EL|front|top|iso]
//                  [--colour bin|height|species|z|local-phi] [--no-legend]
//                  [--cut none|half|slice|x>V...]
//                  [--container outline|walls|none] [--force]
// Reads a pack file, builds its POV-Ray scene (sgmp_render) and renders it to a PNG.
#include "render_command.hpp"

#include <charconv>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_extent.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/render/povray.hpp"
#include "sgmp/render/scene.hpp"
#if SGMP_WITH_METRICS
#include "sgmp/metrics/sphere_values.hpp"
#endif

namespace sgmp::app {
namespace {

/// Largest image side accepted, in pixels.
constexpr int kMaxSide = 8192;

struct RenderOptions {
    std::string pack;
    std::string out;
    std::string size = "800x800";
    std::string view = "iso";
    std::string color = "bin";
    std::string cut = "none";
    std::string container = "outline";
    int threads = 0;
    bool force = false;
    bool no_legend = false;
};

/// Gap tolerance of `--colour z`, over the mean diameter (the report's Z(10⁻³)).
constexpr double kColourContactGap = 1e-3;

#if SGMP_WITH_METRICS
/// The pack's container with its sides (measure.hpp), a malformed key named as input.
Container container_of(const RenderOptions& o, const Pack& pack) {
    try {
        return sgmp::container_of(pack);
    } catch (const std::invalid_argument& e) {
        throw InputError(o.pack, 0, std::string("container: ") + e.what());
    }
}
#endif

/// The per-sphere values and caption of `--colour z` and `--colour local-phi`.
void add_structure_values(const RenderOptions& o, const Pack& pack, render::SceneOptions& s) {
    if (o.color != "z" && o.color != "local-phi") {
        return;
    }
#if SGMP_WITH_METRICS
    s.coloring = render::Coloring::Values;
    if (o.color == "z") {
        s.values = metrics::sphere_contact_numbers(pack.particles, container_of(o, pack),
                                                   kColourContactGap);
        s.caption = {"Z", "gap <= 1e-3 d"};
        return;
    }
    try {
        s.values = metrics::sphere_local_phi(pack.particles, container_of(o, pack));
    } catch (const std::invalid_argument& e) {
        throw InputError(o.pack, 0, std::string("local phi: ") + e.what());
    }
    s.caption = {"local phi", "Voronoi, 1-99 %"};
    s.clip_quantile = 0.01;  // the free surface's open cells would set the colour range
#else
    (void)pack;
    (void)s;
    throw std::runtime_error("--colour " + o.color +
                             ": this sgmp was built without the metrics (SGMP_BUILD_REPORT=OFF)");
#endif
}

using cli::UsageError;

std::optional<std::pair<int, int>> parse_size(const std::string& text) {
    const auto x = text.find('x');
    if (x == std::string::npos) {
        return std::nullopt;
    }
    int w = 0;
    int h = 0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto wr = std::from_chars(begin, begin + x, w);
    const auto hr = std::from_chars(begin + x + 1, end, h);
    if (wr.ec != std::errc() || wr.ptr != begin + x || hr.ec != std::errc() || hr.ptr != end ||
        w < 16 || h < 16 || w > kMaxSide || h > kMaxSide) {
        return std::nullopt;
    }
    return std::pair{w, h};
}

template <class T>
T require(std::optional<T> parsed, const std::string& option, const std::string& value,
          const std::string& rule) {
    if (!parsed) {
        throw ParameterError(option, value, rule);
    }
    return *parsed;
}

render::SceneOptions scene_options(const RenderOptions& o) {
    render::SceneOptions s;
    const auto [w, h] = require(parse_size(o.size), "size", o.size,
                                "must be WIDTHxHEIGHT in pixels, each 16 to " +
                                    std::to_string(kMaxSide) + ", e.g. 800x800");
    s.width = w;
    s.height = h;
    s.view = require(render::parse_view(o.view), "view", o.view,
                     "must be AZ,EL in degrees (EL in [-90, 90]) or front, top, iso");
    const bool structure = o.color == "z" || o.color == "local-phi";
    s.coloring = structure ? render::Coloring::Values
                           : require(render::parse_coloring(o.color), "colour", o.color,
                                     "must be one of bin, height, species, z, local-phi");
    s.legend = !o.no_legend;
    s.cut = require(render::parse_cut(o.cut), "cut", o.cut,
                    "must be none, half, slice or a plane such as z>0 (x|y|z, > or <, a number)");
    s.container = require(render::parse_container_style(o.container), "container", o.container,
                          "must be one of outline, walls, none");
    s.provenance = "pack: " + o.pack + "\nsize=" + o.size + " view=" + o.view +
                   " colour=" + o.color + " cut=" + o.cut + " container=" + o.container;
    return s;
}

std::vector<std::pair<std::string, std::string>> png_texts(const RenderOptions& o,
                                                           const Pack& pack) {
    std::string made_from;
    for (const auto& key : {"generator", "version", "count", "arrangement", "friction", "seed"}) {
        if (const auto value = pack.metadata.get(key)) {
            made_from += (made_from.empty() ? "" : " ") + std::string(key) + "=" + *value;
        }
    }
    return {{"Software", "sgmp render " + std::string(sgmp::version())},
            {"Source", o.pack},
            {"Comment", "size=" + o.size + " view=" + o.view + " colour=" + o.color +
                            " cut=" + o.cut + " container=" + o.container},
            {"Pack", made_from}};
}

int run(const RenderOptions& o) {
    const render::SceneOptions s = scene_options(o);
    const auto povray = render::find_povray();
    if (!povray) {
        throw std::runtime_error(
            "povray was not found on PATH (install the Debian package povray)");
    }
    try {
        check_writable(o.out, o.force);
    } catch (const std::runtime_error& e) {
        throw UsageError(std::string("--out ") + e.what());
    }
    const Pack pack = read_pack_file(o.pack);
    if (pack.particles.empty()) {
        throw InputError(o.pack, 0, "the pack has no particles");
    }
    render::SceneOptions scene_opts = s;
    add_structure_values(o, pack, scene_opts);
    scene_opts.key_text = render::key_font_found();
    if (scene_opts.legend && !scene_opts.key_text) {
        std::fprintf(stderr,
                     "sgmp: warning: POV-Ray's font cyrvetic.ttf was not found (Debian "
                     "povray-includes): the key is drawn without its labels\n");
    }
    std::string scene;
    try {
        scene = render::povray_scene(pack, scene_opts);
    } catch (const std::invalid_argument& e) {
        throw InputError(o.pack, 2, e.what());  // the header line holds the container key
    }
    render::RenderJob job;
    job.scene = scene;
    job.width = s.width;
    job.height = s.height;
    job.out = o.out;
    job.overwrite = o.force;
    job.texts = png_texts(o, pack);
    job.threads = o.threads;
    render::render_png(*povray, job);
    std::printf("sgmp: rendered %zu of %zu spheres, %dx%d -> %s\n",
                render::scene_sphere_count(scene), pack.particles.size(), s.width, s.height,
                o.out.c_str());
    return 0;
}

}  // namespace

RenderCommand register_render(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "a picture of a pack (PNG) rendered with POV-Ray: shaded spheres coloured by "
        "colour bin or height, the container, an optional cut-away");
    cmd->add_option("pack", o->pack, "pack file (extended XYZ or LIGGGHTS dump, .gz ok)")
        ->required();
    cmd->add_option("--out", o->out, "output PNG")->required();
    cmd->add_flag("--force", o->force, "overwrite an existing output file");
    cmd->add_option("--size", o->size, "image size WIDTHxHEIGHT in pixels")->capture_default_str();
    cmd->add_option("--view", o->view,
                    "camera: AZ,EL in degrees (azimuth about Y from +Z toward +X, elevation "
                    "above the horizontal) or front (0,10), top (0,90), iso (35,30)")
        ->capture_default_str();
    cmd->add_option("--colour", o->color,
                    "sphere colours: bin (the colour bins 0-9, Tableau 10), height (viridis "
                    "from the floor to the top), species (a blend's species 1, 2, ... in "
                    "Tableau 10 order: blue, orange, green, ...), z (contacts at gaps <= "
                    "1e-3 d, viridis) or local-phi (Voronoi local packing fraction, viridis "
                    "over its 1-99 % range); "
                    "a colour bar or swatches and a length scale go on the right")
        ->capture_default_str();
    cmd->add_option("--cut", o->cut,
                    "cut-away: none, half (drop the half nearer the camera), slice (keep a slab "
                    "two diameters thick through the axis, face on), or a plane such as z>0 "
                    "(drop the spheres whose centre has z > 0)")
        ->capture_default_str();
    cmd->add_option("--container", o->container,
                    "container: outline (thin edges), walls (translucent floor and far walls), "
                    "none")
        ->capture_default_str();
    cmd->add_flag("--no-legend", o->no_legend,
                  "leave out the key (colour bar or swatches, length scale) and its strip");
    cmd->add_option("--threads", o->threads, "POV-Ray render threads (0: all cores)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    // Errors go to cli::run_main: usage errors exit 2, anything else 1, one line each.
    auto run_command = [o]() -> int { return run(*o); };
    return RenderCommand{cmd, run_command};
}

}  // namespace sgmp::app
