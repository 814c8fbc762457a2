#include "convert_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/cpu_budget.hpp"
#include "sgmp/pack/crowding.hpp"
#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/option_rules.hpp"
#include "sgmp/pack/output_frame.hpp"
#include "sgmp/pack/pack_file.hpp"
#include "sgmp/pack/pack_format.hpp"
#include "sgmp/pack/pack_origin.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/particle_density.hpp"
#include "sgmp/pack/size_modes.hpp"
#include "sgmp/pack/stated_container.hpp"
#include "sgmp/pack/text_precision.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::app {
namespace {

struct ConvertOptions {
    std::string in;
    std::string out;
    std::string to;
    std::size_t frame = 0;        // 0: the last
    double radius = 0.0;          // 0: the file's
    std::string origin = "keep";  // keep | zero
    std::string up = "y";         // y | z
    double length_scale = 0.0;    // 0: unscaled
    std::string length_unit;
    double density = 0.0;   // 0: the data format's 1
    std::string container;  // --container "x_min x_max z_min z_max floor"
    CLI::Option* container_option = nullptr;
    bool force = false;
};

ConvertOptions options;

struct UsageError {
    std::string message;
};

PackFormat output_format(const ConvertOptions& o) {
    if (!o.to.empty()) {
        const auto format = parse_pack_format(o.to);
        if (!format) {
            throw UsageError{"--to '" + o.to + "': must be " + pack_format_choices()};
        }
        return *format;
    }
    const auto format = format_from_extension(o.out);
    if (!format) {
        throw UsageError{"OUT '" + o.out +
                         "': the format cannot be told from the name; name it with --to (" +
                         pack_format_choices() +
                         ") or end the name in .xyz, .xyz.gz, .data, "
                         ".dump, .vtk or .vtp"};
    }
    return *format;
}

/// The one-line warning when overlaps are within the file's text precision.
void warn_on_precision(const PackRead& read) {
    if (!read.decimals) {
        return;
    }
    // Spheres clumped past the hard-sphere limit (crowding.hpp) overlap by more than any
    // text precision, and listing their pairs would take O(N²) (200,000 at one point took
    // 103 s): say so instead.
    if (const auto crowded = overcrowded_cube(read.pack.particles)) {
        std::fprintf(stderr,
                     "sgmp convert: warning: %zu sphere centres in one cube of side 2*r_min: "
                     "spheres overlap by more than the smallest radius, not by text "
                     "precision\n",
                     crowded->centres);
        return;
    }
    // Overlaps count beyond 1e-9 d, as in the metrics (sgmp-compare measure).
    const double d = mean_diameter(read.pack);
    const PrecisionOverlaps found =
        precision_overlaps(read.pack.particles, *read.decimals, 1e-9 * d);
    if (found.within_precision == 0) {
        return;
    }
    std::fprintf(stderr,
                 "sgmp convert: warning: %zu overlaps of at most %.3g d come only from the "
                 "file's text precision (%d decimals)\n",
                 found.within_precision, found.max_overlap / d, *read.decimals);
}

/// The one-line warning when an SGMP pack that was not relaxed becomes a DEM start (a
/// LAMMPS data file): the deposition is no mechanical equilibrium, so DEM rearranges it.
void warn_on_dem_start(const Pack& pack, PackFormat format) {
    if (format != PackFormat::lammps_data) {
        return;
    }
    const auto generator = pack.metadata.get("generator");
    const auto relax = pack.metadata.get("relax");
    if (!generator || *generator != "sgmp" || (relax && *relax != "none")) {
        return;
    }
    std::fprintf(stderr,
                 "sgmp convert: warning: this SGMP pack was not relaxed: as a DEM start it "
                 "rearranges (LAMMPS gran/hertz/history, mu 0.5, gravity: 4.8 %% of the "
                 "spheres of a deposited pack moved more than d/2); pack it with --relax "
                 "frictional for a certified equilibrium\n");
}

void record_provenance(Pack& pack, const ConvertOptions& o) {
    pack.metadata.set("converted_by", "sgmp convert");
    pack.metadata.set("converted_version", std::string(version()));
    pack.metadata.set("converted_from", o.in);
    if (o.frame > 0) {
        pack.metadata.set_integer("converted_frame", static_cast<long long>(o.frame));
    }
    if (o.radius > 0.0) {
        pack.metadata.set_number("converted_radius", o.radius);
    }
}

/// The frame OUT is written in (output_frame.hpp), from --up, --length-scale/--length-unit
/// and --density.
OutputFrame output_frame(const ConvertOptions& o) {
    if (o.length_scale > 0.0 && o.length_unit.empty()) {
        throw UsageError{"--length-scale " + format_number(o.length_scale) +
                         ": name the unit it is in with --length-unit (for example m or um)"};
    }
    if (o.origin == "zero" && (o.up == "z" || o.length_scale > 0.0)) {
        throw UsageError{
            "--origin zero: not with --up z or --length-scale yet (it moves the "
            "container's corner in the testbed's frame, before turning or scaling)"};
    }
    OutputFrame frame;
    frame.up = o.up == "z" ? UpAxis::Z : UpAxis::Y;
    frame.length_scale = o.length_scale > 0.0 ? o.length_scale : 1.0;
    frame.length_unit = o.length_unit;
    if (o.density > 0.0) {
        frame.density = o.density;
    }
    return frame;
}

/// --length-unit without --length-scale: the scale from the pack's `largest_diameter` (a
/// physical length, size_modes.hpp) and its diameters in control-volume sides,
/// L = D_largest · (metres per its unit) / (metres per --length-unit) / d_largest.
void scale_from_pack(const ConvertOptions& o, const Pack& pack, OutputFrame& frame) {
    if (o.length_unit.empty() || o.length_scale > 0.0) {
        return;
    }
    const auto stated = parse_physical_length(pack.metadata.get("largest_diameter").value_or(""));
    const auto to_metres = metres_per_unit(o.length_unit);
    if (!stated || !to_metres) {
        throw UsageError{"--length-unit '" + o.length_unit +
                         "': give --length-scale, the length of one control-volume side in it" +
                         (stated ? " (or a unit of " + std::string(length_units()) +
                                       ", to scale by the pack's largest_diameter)"
                                 : std::string())};
    }
    if (pack.metadata.contains("length_scale")) {
        throw UsageError{"--length-unit '" + o.length_unit +
                         "': the pack is already in a unit; give --length-scale"};
    }
    double largest = 0.0;
    for (const Particle& p : pack.particles) {
        largest = std::max(largest, 2.0 * p.radius);
    }
    if (!(largest > 0.0)) {
        throw UsageError{"--length-unit '" + o.length_unit +
                         "': the pack has no sphere to scale by"};
    }
    frame.length_scale = stated->first * *metres_per_unit(stated->second) / *to_metres / largest;
}

/// --density on a pack that states a density per species would overwrite them all.
void check_density(const ConvertOptions& o, const Pack& pack) {
    if (o.density <= 0.0 || pack.metadata.contains("particle_density")) {
        return;
    }
    if (const auto densities = particle_densities(pack); densities && densities_vary(*densities)) {
        throw UsageError{"--density " + format_number(o.density) +
                         ": the pack states a density per species (size_modes " +
                         pack.metadata.get("size_modes").value_or("") +
                         "); leave --density out to write them"};
    }
}

/// --container, parsed by the header key's parser (stated_container.hpp).
std::optional<StatedContainer> stated_container(const ConvertOptions& o) {
    if (o.container_option == nullptr || o.container_option->count() == 0) {
        return std::nullopt;
    }
    try {
        return StatedContainer{Container::parse(o.container), "--container"};
    } catch (const ParameterError& error) {
        throw UsageError{cli::usage_message(error)};
    }
}

int convert(const ConvertOptions& o) {
    const PackFormat format = output_format(o);
    OutputFrame frame = output_frame(o);
    try {
        check_writable(o.out, o.force);
        if (has_container_file(format)) {
            check_writable(container_file_for(o.out), o.force);
        }
    } catch (const std::runtime_error& e) {
        throw UsageError{std::string("OUT ") + e.what()};
    }
    ReadOptions read_options;
    read_options.threads = usable_threads();  // the pack does not depend on it
    if (o.frame > 0) {
        read_options.frame = o.frame;
    }
    if (o.radius > 0.0) {
        read_options.radius = o.radius;
    }
    read_options.container = stated_container(o);
    PackRead read = read_pack_file(o.in, read_options);
    scale_from_pack(o, read.pack, frame);  // option errors before any warning
    check_density(o, read.pack);
    for (const std::string& warning : read.warnings) {
        std::fprintf(stderr, "sgmp convert: warning: %s: %s\n", o.in.c_str(), warning.c_str());
    }
    warn_on_precision(read);
    warn_on_dem_start(read.pack, format);
    if (o.origin == "zero") {
        (void)move_corner_to_origin(read.pack);
    }
    record_provenance(read.pack, o);
    write_pack_as(o.out, in_output_frame(read.pack, frame), format, WriteOptions{o.force});
    std::printf("sgmp convert: %zu particles (frame %zu of %zu) from %s -> %s (%s)\n",
                read.pack.particles.size(), read.frame, read.frames, o.in.c_str(), o.out.c_str(),
                std::string(to_string(format)).c_str());
    return 0;
}

}  // namespace

CLI::App* register_convert(CLI::App& app) {
    CLI::App* command = app.add_subcommand(
        "convert",
        "convert a pack file (extended XYZ, LAMMPS dump custom or data file) to another "
        "format: " +
            pack_format_choices() + "; the format comes from OUT's name or --to");
    command->add_option("IN", options.in, "input pack file")->required();
    command
        ->add_option("OUT", options.out,
                     "output file: .xyz, .xyz.gz, .data (LAMMPS atom_style sphere), .dump "
                     "(LAMMPS dump custom), .vtk (legacy VTK, ASCII), .vtp (VTK XML, binary; "
                     "smaller and faster at large N); the container goes beside either: "
                     "pack.vtk -> pack.container.vtk)")
        ->required();
    command->add_option("--to", options.to, "output format, " + pack_format_choices());
    command
        ->add_option("--frame", options.frame,
                     "frame of a multi-frame extended XYZ file, counted from 1 (default: "
                     "the last)")
        ->check([](const std::string& text) {
            return seed_rule(text).empty() && text != "0"
                       ? std::string()
                       : std::string("must be a whole number >= 1");
        });
    command
        ->add_option("--radius", options.radius,
                     "radius of every particle (control-volume sides), for files without a "
                     "radius or diameter column; replaces the file's radii otherwise")
        ->check([](const std::string& text) {
            return finite_range_rule(text, 1e-300, 1e300, "(0, 1e300]");
        });
    command
        ->add_option("--origin", options.origin,
                     "keep: positions and box as read; zero: move the pack so that its "
                     "container's corner (x_min, floor, z_min) is at 0, for tools that ignore "
                     "Origin (the shift is recorded as origin_shift)")
        ->check(CLI::IsMember({"keep", "zero"}));
    command
        ->add_option("--up", options.up,
                     "the axis that points up in OUT: y (the testbed's, default) or z "
                     "(LAMMPS, LIGGGHTS, OVITO): each centre (x, y, z) is written as "
                     "(x, -z, y), a right-handed turn; recorded as up_axis, and undone when "
                     "the file is read back")
        ->check(CLI::IsMember({"y", "z"}));
    command
        ->add_option("--length-scale", options.length_scale,
                     "length of one control-volume side in --length-unit: every centre, "
                     "radius and box is multiplied by it (0.01 with m: a side of 1 cm)")
        ->check([](const std::string& text) {
            return finite_range_rule(text, 1e-300, 1e300, "(0, 1e300]");
        });
    command
        ->add_option("--length-unit", options.length_unit,
                     "the unit of --length-scale, recorded as length_unit (m, mm, um, ...)")
        ->check([](const std::string& text) {
            const bool plain = !text.empty() && text.size() <= 32 &&
                               text.find_first_of(" \t\r\n\"'=#") == std::string::npos;
            return plain ? std::string()
                         : std::string("must be 1 to 32 characters, no blank, quote, = or #");
        });
    command
        ->add_option("--density", options.density,
                     "particle density written to a LAMMPS data file (mass = density * "
                     "(pi/6) * diameter^3 in the file's units, e.g. kg/m^3 with m; default 1)")
        ->check([](const std::string& text) {
            return finite_range_rule(text, 1e-300, 1e300, "(0, 1e300]");
        });
    options.container_option = command->add_option(
        "--container", options.container, "walls of IN, \"x_min x_max z_min z_max floor\"; kept");
    command->add_flag("--force", options.force, "overwrite existing output files");
    return command;
}

int run_convert() {
    try {
        return convert(options);
    } catch (const UsageError& e) {
        std::cerr << "sgmp convert: " << printable(e.message) << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "sgmp convert: " << printable(cli::failure_message(e)) << "\n";
        return 1;
    }
}

}  // namespace sgmp::app
