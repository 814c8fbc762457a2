// The pack parameter table (pack_parameters.hpp): its rows round-trip through their text,
// the header records exactly the rows it should with the rows' text, and the batch grid and
// the table agree.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <set>
#include <string>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/engine/pack_parameters.hpp"
#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/pack/random.hpp"

using namespace sgmp;
using namespace sgmp::engine;

BOOST_AUTO_TEST_SUITE(pack_parameter_table)

BOOST_AUTO_TEST_CASE(names_are_unique_snake_case_and_found_in_either_spelling) {
    std::set<std::string> names;
    for (const PackParameter& row : pack_parameters()) {
        BOOST_TEST(names.insert(row.name).second, row.name);
        BOOST_TEST(row.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos);
        BOOST_TEST(!row.help.empty(), row.name);
        BOOST_TEST(!row.rule.empty(), row.name);
        BOOST_TEST(find_pack_parameter(row.name) == &row);
        BOOST_TEST(find_pack_parameter(option_name(row.name)) == &row);
    }
    BOOST_TEST(option_name("relax_settle_limit") == "--relax-settle-limit");
    BOOST_TEST(find_pack_parameter("no_such") == nullptr);
}

BOOST_AUTO_TEST_CASE(every_row_reads_back_its_default_text) {
    const PackRequest defaults;
    for (const PackParameter& row : pack_parameters()) {
        BOOST_TEST(row.default_text == row.format(defaults), row.name);
        if (row.required || row.unset_by_default) {
            continue;
        }
        PackRequest r;
        BOOST_TEST(row.parse(r, row.default_text), row.name);
        BOOST_TEST(row.format(r) == row.default_text, row.name);
    }
}

// Real values round-trip exactly (shortest text that reads back to the same double), over
// 1000 random doubles per row across 40 decades.
BOOST_AUTO_TEST_CASE(numbers_round_trip_exactly) {
    Random random(17);
    for (const PackParameter& row : pack_parameters()) {
        if (row.kind != ValueKind::Number) {
            continue;
        }
        for (int i = 0; i < 1000; ++i) {
            const double value = std::pow(10.0, random.uniform(-20.0, 20.0));
            PackRequest r;
            BOOST_TEST_REQUIRE(row.parse(r, format_number(value)));
            PackRequest again;
            BOOST_TEST_REQUIRE(row.parse(again, row.format(r)));
            BOOST_TEST(row.format(again) == row.format(r));
            BOOST_TEST(row.format(r) == format_number(value), row.name);
        }
    }
}

BOOST_AUTO_TEST_CASE(texts_of_the_wrong_kind_are_refused_with_the_rule) {
    PackRequest r;
    BOOST_CHECK_THROW(set_pack_parameter(r, "relax_stiffness", "abc"), ParameterError);
    BOOST_CHECK_THROW(set_pack_parameter(r, "relax_stages", "2.5"), ParameterError);
    BOOST_CHECK_THROW(set_pack_parameter(r, "gap", "banana"), ParameterError);
    BOOST_CHECK_THROW(set_pack_parameter(r, "no_such", "1"), ParameterError);
    try {
        set_pack_parameter(r, "--gap", "banana");
        BOOST_FAIL("refused");
    } catch (const ParameterError& e) {
        BOOST_TEST(e.name() == "gap");
        BOOST_TEST(e.value() == "banana");
        BOOST_TEST(e.rule() == "must be one of largest, random");
    }
    // A whole number past its type's range is clamped, so the rule (not a wrap) refuses it.
    set_pack_parameter(r, "relax_settle_limit", "99999999999999999999");
    BOOST_TEST(r.relax.settle_limit == std::numeric_limits<int>::max());
    BOOST_CHECK_THROW(validate(r), ParameterError);
    BOOST_CHECK_THROW(set_pack_parameter(r, "count", "-5"), ParameterError);
}

// The header holds exactly the recorded rows, each as its row formats it: a frictional
// relaxed blend (every group recorded), and a plain pack (no relax_* key).
BOOST_AUTO_TEST_CASE(the_header_records_each_row_as_formatted) {
    PackRequest frictional;
    frictional.count = 30;
    frictional.arrangement = Arrangement::LooseRandom;
    set_pack_parameter(frictional, "size_modes", "1:0.5,0.8:0.5");
    set_pack_parameter(frictional, "relax", "frictional");
    set_pack_parameter(frictional, "relax_settle_limit", "40");
    set_pack_parameter(frictional, "sweep_stages", "8,120");
    PackRequest plain;
    plain.count = 30;
    for (const PackRequest& request : {frictional, plain}) {
        const Pack pack = make_pack(request);
        for (const PackParameter& row : pack_parameters()) {
            const auto value = pack.metadata.get(row.name);
            const bool recorded = !row.recorded || row.recorded(request);
            BOOST_TEST(value.has_value() == recorded, row.name);
            if (value && recorded) {
                BOOST_TEST(*value == row.format(request), row.name);
            }
        }
    }
    BOOST_TEST(!make_pack(plain).metadata.get("relax_stiffness").has_value());
}

BOOST_AUTO_TEST_CASE(each_relaxation_mode_has_its_own_stiffness_schedule_and_typed_values_win) {
    // Unset schedule rows take the mode's defaults (relax_schedule); the row's text is the
    // value the relaxation runs, so a header replayed as options gives the same request.
    PackRequest frictionless;
    set_pack_parameter(frictionless, "relax", "frictionless");
    PackRequest frictional;
    set_pack_parameter(frictional, "relax", "frictional");
    const auto text = [](const PackRequest& r, const char* name) {
        return find_pack_parameter(name)->format(r);
    };
    BOOST_TEST(text(frictionless, "relax_stiffness") == "20000");
    BOOST_TEST(text(frictionless, "relax_stages") == "1");
    BOOST_TEST(text(frictionless, "relax_time") == "200");
    BOOST_TEST(text(frictional, "relax_stiffness") == "2000");
    BOOST_TEST(text(frictional, "relax_stages") == "5");
    BOOST_TEST(text(frictional, "relax_time") == "5");
    set_pack_parameter(frictionless, "relax_stiffness", "3e3");
    set_pack_parameter(frictionless, "relax_stages", "2");
    BOOST_TEST(text(frictionless, "relax_stiffness") == "3000");
    BOOST_TEST(text(frictionless, "relax_stages") == "2");
    BOOST_TEST(text(frictionless, "relax_time") == "200");
    PackRequest replayed;
    for (const char* name : {"relax", "relax_stiffness", "relax_stages", "relax_time"}) {
        set_pack_parameter(replayed, name, text(frictionless, name));
    }
    const RelaxSchedule a = relax_schedule(frictionless.relax);
    const RelaxSchedule b = relax_schedule(replayed.relax);
    BOOST_TEST(a.stiffness == b.stiffness);
    BOOST_TEST(a.stages == b.stages);
    BOOST_TEST(a.time == b.time);
    // The rules apply to the schedule run: 10 stages from the default 2e4 would end at
    // 2e13 m*g/d, beyond the 1e12 allowed.
    frictionless.count = 100;
    frictionless.relax.stiffness.reset();
    set_pack_parameter(frictionless, "relax_stages", "10");
    BOOST_CHECK_EXCEPTION(validate(frictionless), ParameterError, [](const ParameterError& e) {
        return std::string(e.what()).find("10: the last stage's stiffness") != std::string::npos;
    });
}

BOOST_AUTO_TEST_SUITE_END()
