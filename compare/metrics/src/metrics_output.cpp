#include "sgmp/metrics/metrics_output.hpp"

#include <cstdint>
#include <functional>
#include <stdexcept>

#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/pack/atomic_file.hpp"
#include "sgmp/pack/version.hpp"

namespace sgmp::metrics {
namespace {

using Json = nlohmann::ordered_json;

Json overlap_json(const OverlapSummary& s) {
    Json worst = Json::array();
    for (const auto& r : s.worst) {
        Json entry;
        entry["id_a"] = r.id_a;
        if (r.id_b >= 0) {
            entry["id_b"] = r.id_b;
        } else {
            entry["id_b"] = nullptr;
        }
        entry["depth_over_d"] = r.depth_over_d;
        worst.push_back(entry);
    }
    return Json{{"count", s.count},
                {"count_any", s.count_any},
                {"max_over_d", s.max_over_d},
                {"mean_over_d", s.mean_over_d},
                {"worst", worst}};
}

/// A blend's per-species structure (species_structure.hpp): per species its origins, count,
/// mean diameter and Z_I(δ); per pair type I ≤ J its bin offset, ρ_J and Z_IJ(δ), Z_JI(δ).
/// The partial g_IJ(r) are the g_I_J columns of g_r.csv.
Json species_json(const SpeciesStructure& s, const std::vector<std::string>& names) {
    Json species = Json::array();
    for (const SpeciesSummary& one : s.species) {
        Json z;
        for (std::size_t t = 0; t < names.size() && t < one.z_mean.size(); ++t) {
            z[names[t]] = one.z_mean[t];
        }
        species.push_back(Json{{"species", one.species},
                               {"origins", one.origins},
                               {"count", one.count},
                               {"diameter_over_d", one.diameter_over_d},
                               {"z_mean", z}});
    }
    Json pairs = Json::array();
    for (const SpeciesPair& pair : s.pairs) {
        Json z_ij;
        Json z_ji;
        for (std::size_t t = 0; t < names.size() && t < pair.z_ij.size(); ++t) {
            z_ij[names[t]] = pair.z_ij[t];
            z_ji[names[t]] = pair.z_ji[t];
        }
        pairs.push_back(
            Json{{"i", pair.i},
                 {"j", pair.j},
                 {"column", "g_" + std::to_string(pair.i) + "_" + std::to_string(pair.j)},
                 {"bin_offset_over_d", pair.bin_offset_over_d},
                 {"density", pair.density},
                 {"z_ij", z_ij},
                 {"z_ji", z_ji}});
    }
    return Json{
        {"definitions", Json{{"z_mean",
                              "Z_I(delta): neighbours of any species within gap delta*d, "
                              "per centre of species I in the region"},
                             {"z_ij",
                              "Z_IJ(delta): neighbours of species J per centre of species I "
                              "in the region"},
                             {"g_I_J",
                              "partial g(r) of origins of species I (centres in the region) "
                              "and neighbours of species J, column g_I_J of g_r.csv; its bin "
                              "k is centred on r_over_d + bin_offset_over_d, so the contact "
                              "distance r_I + r_J is a bin centre"}}},
        {"species", species},
        {"pairs", pairs}};
}

std::string csv_number(double v) {
    return format_number(v);
}

}  // namespace

Json box_json(const Box& box) {
    return Json{{"lo", {box.lo.x(), box.lo.y(), box.lo.z()}},
                {"hi", {box.hi.x(), box.hi.y(), box.hi.z()}}};
}

Json provenance(const std::string& input, const Pack& pack, const MeasureOptions& o) {
    Json keys = Json::object();
    for (const auto& [key, value] : pack.metadata.entries()) {
        keys[key] = value;
    }
    Json parameters;
    if (o.region) {
        parameters["region"] = box_json(*o.region);
    } else {
        parameters["region"] = "control volume";
    }
    parameters["slab_thickness_over_d"] = o.slab_thickness;
    parameters["gr_bin_width_over_d"] = o.gr_bin_width;
    parameters["gr_range_over_d"] = o.gr_range;
    parameters["gr_thesis"] = o.gr_thesis;
    parameters["gr_space"] = o.gr_container_space ? "container" : "centres";
    parameters["gr_density"] = o.gr_density == RdfDensity::Space ? "space" : "neighbours";
    parameters["q6_cutoff"] = o.q6_cutoff;
    parameters["overlap_floor_over_d"] = o.overlap_floor;
    parameters["voronoi"] = o.voronoi;
    return Json{{"tool", "sgmp-compare"},
                {"version", sgmp::version()},
                {"input", input},
                {"input_metadata", keys},
                {"parameters", parameters}};
}

namespace {

/// The metric table's values of `m` into `j`, in its metrics.json order: the headline values
/// (`detail` false) or the detail (true).
void put_metrics(Json& j, const Measurement& m, bool detail) {
    for (const MetricDescriptor* d : ranked_metrics(&MetricDescriptor::json_rank)) {
        if ((d->json_rank >= kJsonDetail) != detail) {
            continue;
        }
        if (const auto v = d->value(m, d->tolerance)) {
            j[d->name] = d->integer ? Json(static_cast<std::int64_t>(*v)) : Json(*v);
        }
    }
}

/// Every metric's definition, by key.
Json definitions_json() {
    Json definitions = Json::object();
    for (const auto& [key, text] : metric_definitions()) {
        definitions[key] = text;
    }
    return definitions;
}

/// How g(r) was counted: bins, origins, the density and its rule, the split pairs.
Json g_r_detail_json(const Rdf& rdf) {
    return Json{{"bin_width_over_d", rdf.bin_width_over_d},
                {"bins", rdf.g.size()},
                {"origins", rdf.origins},
                {"edge_corrected_origins", rdf.corrected_origins},
                {"density", rdf.density},
                {"density_rule", rdf.density_rule == RdfDensity::Space ? "space" : "neighbours"},
                {"space_density", rdf.space_density},
                {"split_pairs", {rdf.split_pairs[0], rdf.split_pairs[1]}},
                {"split_volume", {rdf.split_volume[0], rdf.split_volume[1]}},
                {"space", box_json(rdf.space)}};
}

/// A blend's mixing: the species' volume shares overall and in each height quarter.
Json mixing_json(const MixingProfile& mixing) {
    Json quarters = Json::array();
    const double slab = (mixing.y_high - mixing.y_low) / 4.0;
    for (std::size_t q = 0; q < 4; ++q) {
        quarters.push_back(Json{
            {"y_low", mixing.y_low + static_cast<double>(q) * slab},
            {"y_high", q == 3 ? mixing.y_high : mixing.y_low + static_cast<double>(q + 1) * slab},
            {"volume_shares", mixing.quarters[q]}});
    }
    return Json{{"species", mixing.species},
                {"overall_volume_shares", mixing.overall},
                {"quarters", quarters},
                {"deviation_max", mixing.deviation}};
}

/// A blend's per-species values, each species with its Voronoi local φ where measured.
Json species_with_voronoi(const Measurement& m, const std::vector<std::string>& names) {
    Json species = species_json(*m.species, names);
    if (m.voronoi) {
        for (Json& one : species["species"]) {
            for (const VoronoiSpecies& v : m.voronoi->by_species) {
                if (v.species == one["species"].get<int>()) {
                    one[metric_with(MetricRole::LocalPacking).name] = v.mean;
                    one[metric_with(MetricRole::LocalSpread).name] = v.sd;
                    one["voronoi_phi_global"] = v.global;
                }
            }
        }
    }
    return species;
}

/// The optional parts of metrics.json, each where measured: mixing, size distribution,
/// species and Voronoi cells.
void put_optional_parts(Json& j, const Measurement& m, const std::vector<std::string>& names) {
    if (m.mixing) {
        j["mixing"] = mixing_json(*m.mixing);
    }
    if (m.size_moments) {
        const auto rcp = desmond_weeks_phi_rcp(*m.size_moments);
        j["size_distribution"] = Json{{"polydispersity", m.size_moments->polydispersity},
                                      {"skewness", m.size_moments->skewness},
                                      {"phi_rcp_desmond_weeks", rcp ? Json(*rcp) : Json()}};
    }
    if (m.species) {
        j["species"] = species_with_voronoi(m, names);
    }
    if (m.voronoi) {
        j["voronoi_detail"] = Json{{"cells", m.voronoi->cells},
                                   {"global", m.voronoi->global},
                                   {"cell_volume", m.voronoi->cell_volume},
                                   {"cap_cells", m.voronoi->cap_cells},
                                   {"histogram_bins", m.voronoi->histogram.size()}};
    }
}

}  // namespace

Json metrics_json(const Measurement& m, const Json& prov) {
    Json j;
    j["schema_version"] = kSchemaVersion;
    j["count"] = m.count;
    j["diameter"] = m.mean_diameter;
    const auto& c = m.local.coordination;
    const auto& names = coordination_tolerance_names();
    put_metrics(j, m, false);
    j["region"] = box_json(m.region);
    put_metrics(j, m, true);  // the detail
    j["origins"] = c.origins;
    j["polydisperse"] = m.polydisperse;
    j["radius_min"] = m.min_radius;
    j["radius_max"] = m.max_radius;
    j["container"] = m.container.to_string();
    j["container_source"] = m.container_source;
    j["top"] = m.top;
    j["definitions"] = definitions_json();
    j["sides"] = m.container.periodic ? "periodic" : "walls";
    j["overlaps_detail"] = Json{{"floor_over_d", m.overlaps.floor},
                                {"pairs", overlap_json(m.overlaps.pairs)},
                                {"walls", overlap_json(m.overlaps.walls)}};
    Json pz;
    for (std::size_t t = 0; t < c.tolerances.size(); ++t) {
        pz[names[t]] = c.p_z[t];
    }
    j["p_z"] = pz;
    j["g_r_detail"] = g_r_detail_json(m.local.rdf);
    put_optional_parts(j, m, names);
    j["q6_detail"] = Json{{"cutoff", m.local.bond_order.cutoff},
                          {"origins_with_bonds", m.local.bond_order.origins_with_bonds}};
    if (m.thesis_rdf) {
        j["g_r_thesis_detail"] = Json{{"origin_id", m.thesis_rdf->origin_id},
                                      {"region_count", m.thesis_rdf->region_count},
                                      {"phi_as_density", m.thesis_rdf->phi}};
    }
    j["phi_profile"] =
        Json{{"y0", m.phi_profile.y0},
             {"slab_thickness", m.phi_profile.thickness},
             {"cross_section", "the region's x-z extent, from the floor to the pack top"}};
    j["provenance"] = prov;
    return j;
}

void write_comment_header(std::ostream& out, const Json& prov) {
    for (const auto& [key, value] : prov.items()) {
        out << "# " << key << ": " << value.dump() << '\n';
    }
}

void write_g_r_csv(std::ostream& out, const Measurement& m, const Json& prov) {
    const auto& rdf = m.local.rdf;
    out << "r_over_d,r_lo_over_d,r_hi_over_d,g,pairs,shell_volume";
    if (m.thesis_rdf) {
        out << ",g_thesis";
    }
    if (m.species) {
        for (const SpeciesPair& pair : m.species->pairs) {
            out << ",g_" << pair.i << '_' << pair.j;
        }
    }
    out << '\n';
    write_comment_header(out, prov);
    out << "# r_over_d: bin centre, centre distance over the mean diameter d (also for "
           "polydisperse packs); pairs: origin-neighbour pairs in the bin; shell_volume: summed "
           "edge-corrected shell volume (length units cubed)\n";
    for (std::size_t k = 0; k < rdf.g.size(); ++k) {
        const double w = rdf.bin_width_over_d;
        out << csv_number(rdf.r_over_d[k]) << ',' << csv_number(bin_inner(k, w)) << ','
            << csv_number(bin_outer(k, w)) << ',' << csv_number(rdf.g[k]) << ',' << rdf.pairs[k]
            << ',' << csv_number(rdf.shell_volume[k]);
        if (m.thesis_rdf) {
            out << ',' << csv_number(m.thesis_rdf->g[k]);
        }
        if (m.species) {
            for (const SpeciesPair& pair : m.species->pairs) {
                out << ',' << csv_number(k < pair.g.size() ? pair.g[k] : 0.0);
            }
        }
        out << '\n';
    }
}

void write_phi_y_csv(std::ostream& out, const Measurement& m, const Json& prov) {
    const auto& p = m.phi_profile;
    out << "y_mid,y_lo,y_hi,phi";
    for (const SpeciesPhiProfile& s : m.phi_profile_by_species) {
        out << ",phi_" << s.species;
    }
    out << '\n';
    write_comment_header(out, prov);
    for (std::size_t k = 0; k < p.phi.size(); ++k) {
        out << csv_number(0.5 * (p.y_lo[k] + p.y_hi[k])) << ',' << csv_number(p.y_lo[k]) << ','
            << csv_number(p.y_hi[k]) << ',' << csv_number(p.phi[k]);
        for (const SpeciesPhiProfile& s : m.phi_profile_by_species) {
            out << ',' << csv_number(s.phi[k]);
        }
        out << '\n';
    }
}

void write_voronoi_csv(std::ostream& out, const Measurement& m, const Json& prov) {
    out << "phi_mid,phi_lo,phi_hi,density\n";
    write_comment_header(out, prov);
    out << "# density: of the local packing fraction over the cells in the region (integrates to "
           "1 over phi)\n";
    if (!m.voronoi) {
        return;
    }
    const auto& h = m.voronoi->histogram;
    const double width = 1.0 / static_cast<double>(h.size());
    for (std::size_t k = 0; k < h.size(); ++k) {
        const double lo = static_cast<double>(k) * width;
        out << csv_number(lo + 0.5 * width) << ',' << csv_number(lo) << ','
            << csv_number(lo + width) << ',' << csv_number(h[k]) << '\n';
    }
}

void write_p_z_csv(std::ostream& out, const Measurement& m, const Json& prov) {
    const auto& c = m.local.coordination;
    const auto& names = coordination_tolerance_names();
    std::size_t rows = 0;
    out << "z";
    for (std::size_t t = 0; t < c.tolerances.size(); ++t) {
        out << ",p_tol_" << names[t];
        rows = std::max(rows, c.p_z[t].size());
    }
    out << '\n';
    write_comment_header(out, prov);
    for (std::size_t z = 0; z < rows; ++z) {
        out << z;
        for (std::size_t t = 0; t < c.tolerances.size(); ++t) {
            out << ',' << csv_number(z < c.p_z[t].size() ? c.p_z[t][z] : 0.0);
        }
        out << '\n';
    }
}

void write_pack_metrics(const std::filesystem::path& dir, const std::string& stem,
                        const Measurement& m, const nlohmann::ordered_json& provenance) {
    // A failed write names the file and the reason ("File too large", "No space left").
    const auto write = [&](const std::string& suffix,
                           const std::function<void(std::ostream&)>& produce) {
        write_stream_file(dir / (stem + suffix), produce);
    };
    write(".metrics.json",
          [&](std::ostream& out) { out << metrics_json(m, provenance).dump(2) << "\n"; });
    write("." + metric_with(MetricRole::PairCorrelation).name + ".csv",
          [&](std::ostream& out) { write_g_r_csv(out, m, provenance); });
    write(".phi_y.csv", [&](std::ostream& out) { write_phi_y_csv(out, m, provenance); });
    write(".p_z.csv", [&](std::ostream& out) { write_p_z_csv(out, m, provenance); });
    write(".voronoi_phi.csv", [&](std::ostream& out) { write_voronoi_csv(out, m, provenance); });
}

}  // namespace sgmp::metrics
