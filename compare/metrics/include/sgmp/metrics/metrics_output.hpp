#pragma once
/// @file metrics_output.hpp
/// Per-pack outputs: the metrics JSON (count, diameter, the metrics of metric_descriptors.hpp
/// in their json_rank order, region, the detail) and the curve CSVs (g_r, phi_y, p_z, voronoi_phi), each with its header
/// row first, then '#' provenance lines (csv_text.hpp).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "sgmp/metrics/measure.hpp"

namespace sgmp::metrics {

/// Version of every JSON layout sgmp-compare writes (key `schema_version`); raised when a
/// key changes meaning or disappears. 2: centred g(r) bins, g's density from the
/// neighbours, split_ratio, verdicts agree / differ / inconclusive.
inline constexpr int kSchemaVersion = 2;

/// What made an output: tool, version, input path, the input's provenance and the options.
nlohmann::ordered_json provenance(const std::string& input, const Pack& pack,
                                  const MeasureOptions& options);

/// Metrics JSON of one pack. `provenance` is stored under "provenance".
nlohmann::ordered_json metrics_json(const Measurement& m, const nlohmann::ordered_json& provenance);

/// A box as {"lo": [x, y, z], "hi": [x, y, z]}.
nlohmann::ordered_json box_json(const Box& box);

void write_g_r_csv(std::ostream& out, const Measurement& m,
                   const nlohmann::ordered_json& provenance);
void write_phi_y_csv(std::ostream& out, const Measurement& m,
                     const nlohmann::ordered_json& provenance);
void write_p_z_csv(std::ostream& out, const Measurement& m,
                   const nlohmann::ordered_json& provenance);
/// The distribution of the Voronoi local packing fraction (rows only when measured).
void write_voronoi_csv(std::ostream& out, const Measurement& m,
                       const nlohmann::ordered_json& provenance);

/// The provenance as "# key: value" comment lines (one JSON value per line), written right
/// after a CSV's header row (the layout of csv_text.hpp).
/// Writes the per-pack outputs of `measure` into directory `dir` (one being written
/// atomically): <stem>.metrics.json, .g_r.csv, .phi_y.csv, .p_z.csv, .voronoi_phi.csv.
/// Throws std::runtime_error when a file cannot be written.
void write_pack_metrics(const std::filesystem::path& dir, const std::string& stem,
                        const Measurement& m, const nlohmann::ordered_json& provenance);

void write_comment_header(std::ostream& out, const nlohmann::ordered_json& provenance);

}  // namespace sgmp::metrics
