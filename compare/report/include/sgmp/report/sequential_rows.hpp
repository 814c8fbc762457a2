#pragma once
/// @file sequential_rows.hpp
/// Verdicts of a candidate (SGMP) group judged look by look as its seeds are added in blocks
/// (group_sequential.hpp), against a fixed reference group.
///
/// Look k sees the first n_k packs of the candidate group in manifest order and runs the
/// row's equivalence test at the nominal level α_k of its boundary. The row's verdict is
/// that of the first look that decides (`agree` or `differ`), and its numbers are that
/// look's; later seeds never change it. A row no look has decided is `inconclusive`: at
/// the design's last look it is final; before it, more seeds are planned. Such a row names
/// the side that limits it (MetricRow::limited_by):
///   candidate  a planned look with more seeds decides it at the same estimate and scatter
///              (seeds_to_decide: the candidate seeds in all);
///   reference  no planned look does, but more reference pours would, the candidate at the
///              last look (pours_to_decide; the test at the last look's level);
///   candidate  neither, but more candidate seeds than --max-seeds would (seeds_to_decide
///              above it);
///   both       no side alone up to 10⁴, but both grown in their present proportion would
///              (seeds_to_decide candidate seeds and pours_to_decide pours, the smallest
///              such pair, at the last look's level);
///   ""         not even both up to 10⁴ seeds (the estimate sits on the margin).

#include <cstddef>
#include <string>
#include <vector>

#include "sgmp/report/agreement.hpp"
#include "sgmp/report/group_sequential.hpp"

namespace sgmp::report {

/// The most seeds or pours a row's projection names.
inline constexpr std::size_t kMostProjected = 10000;

/// Judges every judged row of `comparison` (verdict not info, rule "margin") look by look
/// with `candidate` (in manifest order) against `reference`, as the header says.
void judge_sequentially(Comparison& comparison, const std::vector<const PackSummary*>& candidate,
                        const std::vector<const PackSummary*>& reference,
                        const SequentialDesign& design, BoundaryCache& cache);

/// A candidate group at one count with a row still undecided before its last look.
struct SeedsNeeded {
    std::string group;
    std::size_t count = 0;
    std::size_t seeds_now = 0;   // packs the group holds at this count
    std::size_t seeds_next = 0;  // packs at its next look
    std::size_t rows = 0;        // its undecided rows, against every reference
};

/// Every (candidate group, count) with an undecided sequential row and a planned look still
/// ahead, in report order: every such row gets more seeds, whichever side limits it (the
/// projection holds the estimate fixed; the estimate moves as seeds come).
std::vector<SeedsNeeded> seeds_needed(const Report& report, const SequentialDesign& design);

/// An undecided sequential row in words: its look, and the side and count that would
/// decide it, e.g. "look 3 of 11 at 13 seeds; limited by the reference: 31 pours decide".
std::string sequential_note(const MetricRow& row);

/// report.csv's columns `look,looks,alpha_spent,nominal_alpha,limited_by,pours_to_decide` of
/// a row (empty fields for a fixed-sample row).
std::string sequential_csv_fields(const MetricRow& row);

/// seeds-needed.csv: `mode,count,seeds_now,seeds_next,rows`, header first (fields quoted when
/// they hold a comma or quote).
std::string render_seeds_needed_csv(const std::vector<SeedsNeeded>& needed);

}  // namespace sgmp::report
