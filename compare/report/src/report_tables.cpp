// The report's tidy tables: report.csv and report.json (report_render.hpp).
#include <sstream>

#include "sgmp/metrics/csv_text.hpp"
#include "sgmp/metrics/metrics_output.hpp"
#include "sgmp/pack/metadata.hpp"
#include "sgmp/pack/version.hpp"
#include "sgmp/report/report_render.hpp"
#include "sgmp/report/sequential_rows.hpp"

namespace sgmp::report {

using metrics::kSchemaVersion;
using metrics::write_csv_preamble;

namespace {

using Json = nlohmann::ordered_json;

}  // namespace

std::string render_csv(const Report& report, const ReportContext& context) {
    std::ostringstream csv;
    csv << "count,candidate,reference,metric,unit,kind,candidate_n,candidate_mean,candidate_sd,"
           "reference_n,reference_mean,reference_sd,difference,seed_spread,model_spread,"
           "tolerance,tolerance_rule,ratio,power,verdict,margin,ci_low,ci_high,mdd,p_agree,"
           "p_differ,seeds_to_decide,look,looks,alpha_spent,nominal_alpha,limited_by,"
           "pours_to_decide\n";
    write_csv_preamble(csv, "sgmp-compare", context.command, rule_statements());
    for (const auto& c : report.comparisons) {
        for (const auto& row : c.rows) {
            const bool scalar = row.kind == MetricKind::Scalar;
            const auto value = [&](double v) { return scalar ? format_number(v) : std::string(); };
            csv << c.count << ',' << csv_field(c.candidate) << ',' << csv_field(c.reference) << ','
                << row.name << ',' << csv_field(row.unit) << ',' << (scalar ? "scalar" : "curve")
                << ',' << (row.look > 0 ? row.candidate_n : c.candidate_packs) << ','
                << value(row.candidate_mean) << ',' << value(row.candidate_sd) << ','
                << c.reference_packs << ',' << value(row.reference_mean) << ','
                << value(row.reference_sd) << ',' << format_number(row.difference) << ','
                << format_number(row.seed_spread) << ',' << format_number(row.model_spread) << ','
                << format_number(row.tolerance) << ',' << row.tolerance_rule << ','
                << (row.ratio ? format_number(*row.ratio) : "") << ',' << (row.power ? "yes" : "no")
                << ',' << to_string(row.verdict) << ',' << format_number(row.margin) << ','
                << format_number(row.ci_low) << ',' << format_number(row.ci_high) << ','
                << format_number(row.mdd) << ',' << format_number(row.p_agree) << ','
                << format_number(row.p_differ) << ','
                << (row.seeds_to_decide ? std::to_string(*row.seeds_to_decide) : "") << ','
                << sequential_csv_fields(row) << '\n';
        }
    }
    return csv.str();
}

Json render_json(const Report& report, const ReportContext& context) {
    Json j;
    j["schema_version"] = kSchemaVersion;
    j["tool"] = "sgmp-compare";
    j["version"] = sgmp::version();
    j["command"] = context.command;
    j["parameters"] = context.parameters;
    j["rules"] = rule_statements();
    Json metrics;
    for (const auto& rule : metric_rules()) {
        metrics[rule.name] = Json{{"label", rule.label},
                                  {"unit", rule.unit},
                                  {"kind", rule.kind == MetricKind::Scalar ? "scalar" : "curve"},
                                  {"margin", rule.margin},
                                  {"judged", rule.judged}};
    }
    j["metrics"] = metrics;
    j["g_r_range_over_d"] = {kGrCompareFrom, kGrCompareTo};
    Json groups = Json::array();
    for (const auto& g : report.groups) {
        Json packs = Json::array();
        for (const auto& p : g.packs) {
            Json prov = Json::object();
            for (const auto& [k, v] : p.provenance) {
                prov[k] = v;
            }
            Json scalars;
            for (const auto& rule : metric_rules()) {
                if (rule.kind == MetricKind::Scalar) {
                    scalars[rule.name] = p.scalar(rule.name);
                }
            }
            packs.push_back(Json{{"file", p.source},
                                 {"count", p.count},
                                 {"diameter", p.diameter},
                                 {"metrics", scalars},
                                 {"provenance", prov}});
        }
        groups.push_back(Json{{"label", g.label}, {"packs", packs}});
    }
    j["groups"] = groups;
    Json comparisons = Json::array();
    for (const auto& c : report.comparisons) {
        Json rows = Json::array();
        for (const auto& row : c.rows) {
            const bool scalar = row.kind == MetricKind::Scalar;
            rows.push_back(
                Json{{"metric", row.name},
                     {"unit", row.unit},
                     {"candidate_mean", scalar ? Json(row.candidate_mean) : Json()},
                     {"candidate_sd", scalar ? Json(row.candidate_sd) : Json()},
                     {"reference_mean", scalar ? Json(row.reference_mean) : Json()},
                     {"reference_sd", scalar ? Json(row.reference_sd) : Json()},
                     {"difference", row.difference},
                     {"seed_spread", row.seed_spread},
                     {"model_spread", row.model_spread},
                     {"tolerance", row.tolerance},
                     {"tolerance_rule", row.tolerance_rule},
                     {"ratio", row.ratio ? Json(*row.ratio) : Json()},
                     {"power", row.power},
                     {"margin", row.margin},
                     {"ci_low", finite_or_null(row.ci_low)},
                     {"ci_high", finite_or_null(row.ci_high)},
                     {"mdd", finite_or_null(row.mdd)},
                     {"p_agree", row.p_agree},
                     {"p_differ", row.p_differ},
                     {"seeds_to_decide", row.seeds_to_decide ? Json(*row.seeds_to_decide) : Json()},
                     {"look", row.look},
                     {"looks", row.looks},
                     {"candidate_n", row.look > 0 ? row.candidate_n : c.candidate_packs},
                     {"alpha_spent", row.alpha_spent},
                     {"nominal_alpha", row.nominal_alpha},
                     {"limited_by", row.limited_by},
                     {"pours_to_decide", row.pours_to_decide ? Json(*row.pours_to_decide) : Json()},
                     {"verdict", to_string(row.verdict)}});
        }
        comparisons.push_back(Json{{"count", c.count},
                                   {"candidate", c.candidate},
                                   {"reference", c.reference},
                                   {"candidate_packs", c.candidate_packs},
                                   {"reference_packs", c.reference_packs},
                                   {"differ", c.count_of(Verdict::Differ)},
                                   {"invalid", c.invalid},
                                   {"metrics", rows}});
    }
    j["comparisons"] = comparisons;
    j["notes"] = report.notes;
    j["plots"] = Json{
        {"made", context.plots_made}, {"note", context.plots_note}, {"files", context.plot_files}};
    return j;
}

}  // namespace sgmp::report
