// The cross-validation's machine-readable views (crossval_render.hpp): crossval.json and
// headline.csv.
#include <cmath>
#include <sstream>

#include "crossval_views.hpp"
#include "sgmp/metrics/csv_text.hpp"
#include "sgmp/metrics/metric_descriptors.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/report/crossval_render.hpp"
#include "sgmp/report/report_render.hpp"
#include "sgmp/report/species_matrix.hpp"

namespace sgmp::report {

using metrics::kSchemaVersion;
using metrics::write_csv_preamble;
namespace {

using detail::headline_scalars;
using Json = nlohmann::ordered_json;

std::string number_or_empty(const std::optional<double>& v) {
    return v ? format_number(*v) : std::string();
}

Json optional_json(const std::optional<double>& v) {
    return v ? Json(*v) : Json();
}

Json tuning_json(const CrossValidation& cv) {
    Json list = Json::array();
    for (const auto& t : cv.tuning) {
        list.push_back({{"group", t.group},
                        {"parameter", t.parameter},
                        {"value", t.value},
                        {"reference", t.reference},
                        {"count", t.count},
                        {"seeds", t.seeds},
                        {"note", t.note}});
    }
    return list;
}

/// {"classes": [...], "parameters": {key: [value per class]}}.
Json dem_parameters_json(const CrossValidation& cv) {
    const DemParameterTable& t = cv.dem_parameters;
    Json parameters = Json::object();
    for (std::size_t k = 0; k < t.keys.size(); ++k) {
        parameters[t.keys[k]] = t.values[k];
    }
    return {{"classes", t.classes}, {"parameters", parameters}};
}

Json class_pairs_json(const CrossValidation& cv) {
    Json pairs = Json::array();
    for (const auto& p : cv.class_pairs) {
        pairs.push_back({{"a", p.a},
                         {"b", p.b},
                         {"one_family", p.one_family()},
                         {"decision", to_string(p.record.decision)},
                         {"agree", p.record.agree},
                         {"differ", p.record.differ},
                         {"differ_familywise", p.record.differ_familywise},
                         {"inconclusive", p.record.inconclusive}});
    }
    return pairs;
}

}  // namespace

std::string render_headline_csv(const CrossValidation& cv, const std::string& command) {
    std::ostringstream csv;
    csv << "count,candidate,reference,metric,candidate_mean,candidate_sd,reference_mean,"
           "reference_sd,tolerance,ratio,verdict,margin,ci_low,ci_high,mdd,candidate_seconds,"
           "reference_seconds,"
           "speedup_vs_reference,thesis_seconds,thesis_phi,speedup_vs_thesis,diameter,"
           "start_height,thesis_start_height\n";
    write_csv_preamble(csv, "sgmp-compare crossval", command, rule_statements());
    for (const auto& row : cv.rows) {
        for (const auto& v : row.against) {
            if (v.rows.empty()) {
                continue;
            }
            for (const auto& name : headline_metrics()) {
                const auto& m = v.row(name);
                const bool scalar = m.kind == MetricKind::Scalar;
                csv << row.count << ',' << csv_field(row.group) << ',' << csv_field(v.reference)
                    << ',' << name << ',' << (scalar ? format_number(m.candidate_mean) : "") << ','
                    << (scalar ? format_number(m.candidate_sd) : "") << ','
                    << (scalar ? format_number(m.reference_mean) : "") << ','
                    << (scalar ? format_number(m.reference_sd) : "") << ','
                    << format_number(m.tolerance) << ',' << (m.ratio ? format_number(*m.ratio) : "")
                    << ',' << to_string(m.verdict) << ',' << format_number(m.margin) << ','
                    << format_number(m.ci_low) << ',' << format_number(m.ci_high) << ','
                    << format_number(m.mdd) << ',' << number_or_empty(row.seconds) << ','
                    << number_or_empty(v.reference_seconds) << ',' << number_or_empty(v.speedup)
                    << ',' << (row.thesis ? format_number(row.thesis->runtime_seconds) : "") << ','
                    << (row.thesis ? format_number(row.thesis->packing_fraction) : "") << ','
                    << number_or_empty(row.thesis_speedup) << ',' << format_number(row.diameter)
                    << ',' << number_or_empty(row.start_height) << ','
                    << (row.thesis_start ? format_number(row.thesis_start->starting_height) : "")
                    << '\n';
            }
        }
    }
    return csv.str();
}

Json crossval_json(const CrossValidation& cv) {
    Json rows = Json::array();
    for (const auto& row : cv.rows) {
        Json against = Json::array();
        for (const auto& v : row.against) {
            if (v.rows.empty()) {
                continue;  // not compared at this count
            }
            Json metrics = Json::object();
            for (const auto& m : v.rows) {
                metrics[m.name] = {{"verdict", to_string(m.verdict)},
                                   {"ratio", m.ratio ? Json(*m.ratio) : Json()},
                                   {"reference_mean",
                                    m.kind == MetricKind::Scalar ? Json(m.reference_mean) : Json()},
                                   {"tolerance", m.tolerance},
                                   {"margin", m.margin},
                                   {"ci_low", finite_or_null(m.ci_low)},
                                   {"ci_high", finite_or_null(m.ci_high)},
                                   {"mdd", finite_or_null(m.mdd)}};
            }
            against.push_back({{"reference", v.reference},
                               {"reference_seconds", optional_json(v.reference_seconds)},
                               {"speedup", optional_json(v.speedup)},
                               {"metrics", metrics}});
        }
        Json item{{"candidate", row.group},
                  {"count", row.count},
                  {"packs", row.packs},
                  {"diameter", row.diameter},
                  {"seconds", optional_json(row.seconds)}};
        for (const metrics::MetricDescriptor* d : headline_scalars()) {
            item[d->name] = row.value(d->name);
        }
        item["against"] = against;
        if (row.thesis) {
            item["thesis"] = {{"table", row.thesis->table},
                              {"runtime_seconds", row.thesis->runtime_seconds},
                              {metrics::metric_with(metrics::MetricRole::PackingFraction).name,
                               row.thesis->packing_fraction}};
            item["speedup_vs_thesis"] = optional_json(row.thesis_speedup);
        }
        if (row.start_height) {
            item["start_height"] = *row.start_height;
        }
        if (row.thesis_start) {
            item["thesis_start"] = {{"table", row.thesis_start->table},
                                    {"grid", row.thesis_start->grid},
                                    {"starting_height", row.thesis_start->starting_height}};
        }
        rows.push_back(item);
    }
    Json stand_ins = Json::array();
    for (const auto& s : cv.stand_ins) {
        stand_ins.push_back({{"candidate", s.candidate},
                             {"reference", s.reference},
                             {"stands_in", s.stands_in()},
                             {"decision", to_string(s.decision)},
                             {"invalid", s.invalid},
                             {"agree", s.agree},
                             {"differ", s.differ},
                             {"differ_familywise", s.differ_familywise},
                             {"inconclusive", s.inconclusive},
                             {"counts", s.counts},
                             {"counts_standing", s.counts_standing},
                             {"speedup", optional_json(s.speedup)},
                             {"speedup_count", s.speedup_count}});
    }
    return {{"schema_version", kSchemaVersion},
            {"candidates", cv.candidates},
            {"references", cv.references},
            {"counts", cv.counts},
            {"stand_ins", stand_ins},
            {"class_pairs", class_pairs_json(cv)},
            {"tuning", tuning_json(cv)},
            {"dem_parameters", dem_parameters_json(cv)},
            {"headline", rows}};
}

}  // namespace sgmp::report
