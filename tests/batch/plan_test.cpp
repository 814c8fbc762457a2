// Seed lists, plans, output patterns and shards: the job list a sweep makes.
#include <boost/test/unit_test.hpp>
#include <numeric>
#include <set>
#include <stdexcept>

#include "sgmp/batch/out_pattern.hpp"
#include "sgmp/batch/seed_list.hpp"
#include "sgmp/batch/shard.hpp"
#include "sgmp/cli/run_main.hpp"
#include "sgmp/pack/parameter_error.hpp"

using namespace sgmp::batch;

namespace {

/// The one line a command shows for the error f throws: a ParameterError as the option is
/// typed (sgmp/cli/run_main.hpp), anything else by its text.
std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const sgmp::ParameterError& e) {
        return sgmp::cli::usage_message(e);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no error)";
}

Grid grid_of(std::vector<std::string> counts, std::vector<std::string> arrangements,
             std::vector<std::uint64_t> seeds) {
    Grid grid;
    grid.values[parameter_index("count")] = std::move(counts);
    grid.values[parameter_index("arrangement")] = std::move(arrangements);
    grid.seeds = std::move(seeds);
    return grid;
}

}  // namespace

BOOST_AUTO_TEST_CASE(seed_lists_expand_ranges_in_order) {
    BOOST_TEST(parse_seed_list("7") == (std::vector<std::uint64_t>{7}));
    BOOST_TEST(parse_seed_list("1,5,9-12") == (std::vector<std::uint64_t>{1, 5, 9, 10, 11, 12}));
    const auto many = parse_seed_list("1-100000");
    BOOST_TEST(many.size() == 100000u);
    BOOST_TEST(many.front() == 1u);
    BOOST_TEST(many.back() == 100000u);
    BOOST_TEST(parse_seed_list("18446744073709551615").front() == 18446744073709551615ull);
}

BOOST_AUTO_TEST_CASE(bad_seed_lists_name_the_value_and_the_rule) {
    BOOST_TEST(message_of([] { parse_seed_list("5-1"); }) ==
               "--seeds 5-1: range 5-1 runs backwards (A must not exceed B)");
    for (const char* bad : {"x", "", "1,,2", "1-", "-3", "1-2-3", "18446744073709551616", "2,"}) {
        BOOST_TEST(
            message_of([&] {
                parse_seed_list(bad);
            }).rfind(std::string(*bad ? "--seeds " : "--seeds") + bad + ": must be seeds S", 0) ==
                0u,
            bad);
    }
    BOOST_TEST(message_of([] { parse_seed_list("1-3,2"); }) ==
               "--seeds 1-3,2: seed 2 appears twice");
    BOOST_TEST(message_of([] { parse_seed_list("0-18446744073709551615"); }) ==
               "--seeds 0-18446744073709551615: holds more than 10000000 seeds");
}

BOOST_AUTO_TEST_CASE(plan_orders_jobs_by_parameters_then_seeds) {
    Grid grid = grid_of({"100", "200"}, {"loose-random", "small-dense"}, {3, 1});
    grid.values[parameter_index("relax")] = {"none", "frictionless"};
    const Plan plan = make_plan(grid);
    BOOST_TEST(plan.job_count() == 16u);
    const auto count = parameter_index("count");
    const auto arrangement = parameter_index("arrangement");
    const auto relax = parameter_index("relax");
    // The first parameter outermost, relax (later in the table) faster, seeds fastest.
    BOOST_TEST(plan.values(0)[count] == "100");
    BOOST_TEST(plan.values(0)[relax] == "none");
    BOOST_TEST(plan.seed(0) == 3u);
    BOOST_TEST(plan.seed(1) == 1u);
    BOOST_TEST(plan.values(2)[relax] == "frictionless");
    BOOST_TEST(plan.values(4)[arrangement] == "small-dense");
    BOOST_TEST(plan.values(8)[count] == "200");
    BOOST_TEST(plan.values(15)[relax] == "frictionless");
    BOOST_TEST(plan.values(0)[parameter_index("circle-factor")] == "50");  // default filled
    BOOST_TEST(plan.varies[relax]);
    BOOST_TEST(!plan.varies[parameter_index("gap")]);
    // Every job is a distinct (combination, seed).
    std::set<std::pair<ParameterValues, std::uint64_t>> distinct;
    for (std::size_t j = 0; j < plan.job_count(); ++j) {
        distinct.insert({plan.values(j), plan.seed(j)});
    }
    BOOST_TEST(distinct.size() == plan.job_count());
}

BOOST_AUTO_TEST_CASE(plan_refuses_empty_grids_and_bad_values) {
    BOOST_TEST(message_of([] { make_plan(grid_of({}, {"small-dense"}, {1})); }) ==
               "--count: the grid is empty; give at least one value");
    BOOST_TEST(message_of([] { make_plan(grid_of({"10"}, {}, {1})); }) ==
               "--arrangement: the grid is empty; give at least one value");
    BOOST_TEST(message_of([] { make_plan(grid_of({"10"}, {"small-dense"}, {})); }) ==
               "--seeds: the grid is empty; give at least one seed");
    BOOST_TEST(message_of([] {
                   make_plan(grid_of({"10", "0"}, {"small-dense"}, {1}));
               }) == "--count 0: must be between 1 and 10000000");
    BOOST_TEST(message_of([] {
                   make_plan(grid_of({"10"}, {"dense"}, {1}));
               }).rfind("--arrangement dense: must be one of", 0) == 0u);
    BOOST_TEST(message_of([] {
                   make_plan(grid_of({"10", "10"}, {"small-dense"}, {1}));
               }) == "--count 10: is listed twice (each value once)");
    Grid g = grid_of({"10"}, {"small-dense"}, {1});
    g.values[parameter_index("momentum")] = {"0", "1.5"};
    BOOST_TEST(message_of([&] { make_plan(g); }).find("--momentum") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(patterns_name_every_job_apart) {
    const Plan plan = make_plan(grid_of({"100", "200"}, {"small-dense"}, {1, 2}));
    const OutPattern pattern("p/{arrangement}/n{count}-s{seed}.xyz.gz", plan);
    BOOST_TEST(pattern.expand(plan, 0) == "p/small-dense/n100-s1.xyz.gz");
    BOOST_TEST(pattern.expand(plan, 3) == "p/small-dense/n200-s2.xyz.gz");
    BOOST_TEST(OutPattern("{{j}}{job}.xyz", plan).expand(plan, 3) == "{j}3.xyz");
    BOOST_TEST(OutPattern("{phi-target}-{count}-{seed}", plan).expand(plan, 0) == "0.63-100-1");
    BOOST_TEST(message_of([&] { OutPattern("n{count}.xyz", plan); }) ==
               "--out-pattern n{count}.xyz: must hold {seed} (or {job}): the batch has several "
               "seeds");
    BOOST_TEST(message_of([&] { OutPattern("s{seed}.xyz", plan); }) ==
               "--out-pattern s{seed}.xyz: must hold {count} (or {job}): the batch gives it "
               "several values");
    BOOST_TEST(message_of([&] { OutPattern("{colour}{job}", plan); }).find("{colour} is no") !=
               std::string::npos);
    BOOST_TEST(message_of([&] { OutPattern("{job", plan); }).find("never closed") !=
               std::string::npos);
}

BOOST_AUTO_TEST_CASE(shards_and_ranks_partition_the_jobs) {
    BOOST_TEST(parse_shard("3/40").index == 3u);
    BOOST_TEST(parse_shard("3/40").count == 40u);
    for (const char* bad : {"0/4", "5/4"}) {
        BOOST_TEST(message_of([&] { parse_shard(bad); }) ==
                   "--shard " + std::string(bad) + ": I must lie in 1..4");
    }
    for (const char* bad : {"x", "1/0", "1", "1/", "/2", "1/2/3"}) {
        BOOST_TEST(message_of([&] { parse_shard(bad); }).find(": must be I/N") != std::string::npos,
                   bad);
    }
    // Every job exactly once over shards x ranks, each list in job order, round-robin.
    const std::size_t jobs = 103;
    std::vector<int> seen(jobs, 0);
    for (std::size_t i = 1; i <= 4; ++i) {
        for (std::size_t r = 0; r < 3; ++r) {
            const auto mine = assigned_jobs(jobs, Shard{i, 4}, r, 3);
            BOOST_TEST(std::is_sorted(mine.begin(), mine.end()));
            for (const std::size_t j : mine) {
                BOOST_TEST(j % 4 == i - 1);
                ++seen[j];
            }
        }
    }
    BOOST_TEST(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(jobs));
    BOOST_TEST(assigned_jobs(7, Shard{2, 3}) == (std::vector<std::size_t>{1, 4}));
}
