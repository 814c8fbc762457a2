#pragma once
/// @file crossval.hpp
/// The cross-validation view of an agreement report: SGMP arrangements (candidate groups)
/// against DEM friction classes (reference groups), one headline row per arrangement and
/// particle count — φ of the control volume, mean coordination Z at δ = 10⁻² and the g(r)
/// distance ratio against each reference, with verdicts — and the thesis' runtime and φ
/// beside ours with the speed-up factor (thesis runtime / our mean runtime), and the
/// height of the starting arrangement beside the thesis' (Tables 6.2, 7.2, 8.2).

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sgmp/compare/agreement.hpp"
#include "sgmp/compare/manifest.hpp"
#include "sgmp/compare/thesis_table.hpp"

namespace sgmp::compare {

/// Metric keys of the headline (fixed names of the per-pack JSON).
inline constexpr const char* kHeadlinePhi = "phi";
inline constexpr const char* kHeadlineZ = "z_mean_tol_1e-2";

/// One candidate group at one count against one reference group.
struct HeadlineVerdict {
    std::string reference;
    double phi_reference = 0.0;
    double phi_tolerance = 0.0;
    bool phi_agree = false;
    double z_reference = 0.0;
    double z_tolerance = 0.0;
    bool z_agree = false;
    std::optional<double> gr_ratio;
    bool gr_agree = false;
    std::optional<double> gr_beyond_contact_ratio;  // on [1.1·d, 5·d], informative
};

struct HeadlineRow {
    std::string group;
    std::size_t count = 0;
    std::size_t packs = 0;
    std::optional<double> seconds;  // mean wall seconds per pack
    double diameter = 0.0;
    double phi = 0.0;
    double z = 0.0;
    std::vector<HeadlineVerdict> against;  // in reference order
    std::optional<ThesisResult> thesis;
    std::optional<double> speedup;       // thesis runtime / seconds
    std::optional<double> start_height;  // mean `start_height` key of the packs
    std::optional<ThesisStart> thesis_start;
};

struct CrossValidation {
    std::vector<std::string> candidates;  // group labels in manifest order
    std::vector<std::string> references;
    std::vector<HeadlineRow> rows;  // by candidate group, then count
};

/// The thesis' published tables (either may be empty).
struct ThesisTables {
    std::vector<ThesisResult> results;
    std::vector<ThesisStart> starts;
};

/// Builds the headline from `report` (which must compare every candidate group with every
/// reference group), the manifest (for runtimes) and the thesis' tables.
CrossValidation cross_validate(const Report& report, const std::vector<ManifestEntry>& manifest,
                               const ThesisTables& thesis);

/// The (candidate, reference) group index pairs to compare: every candidate against every
/// reference, groups in manifest order.
struct GroupPlan {
    std::vector<std::string> labels;
    std::vector<std::vector<std::string>> paths;  // per label
    std::vector<std::pair<std::size_t, std::size_t>> comparisons;
};
GroupPlan plan_groups(const std::vector<ManifestEntry>& manifest);

/// Plain-text headline table for the terminal.
std::string render_headline_text(const CrossValidation& cv);
/// Markdown sections: a summary of where the candidates agree and where not, the headline
/// table, and the thesis beside ours.
std::string render_crossval_markdown(const CrossValidation& cv);
/// The headline as CSV (one row per candidate group, count and reference).
std::string render_headline_csv(const CrossValidation& cv);
nlohmann::ordered_json crossval_json(const CrossValidation& cv);

}  // namespace sgmp::compare
