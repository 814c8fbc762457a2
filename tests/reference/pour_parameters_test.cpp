// The pour parameter table (pour_parameters.hpp): rows round-trip through their text,
// validate() refuses each rule's edge, and the header keys carry their units.
#include <boost/test/unit_test.hpp>
#include <set>
#include <string>

#include "sgmp/pack/parameter_error.hpp"
#include "sgmp/reference/pour_parameters.hpp"

using namespace sgmp;
using namespace sgmp::reference;

namespace {

PourParams valid() {
    PourParams p;
    p.count = 150;
    return p;
}

/// The name of the parameter validate() refuses after `row` parses `text`, or "".
std::string refused_after(const std::string& name, const std::string& text) {
    PourParams p = valid();
    for (const PourParameter& row : pour_parameters()) {
        if (row.name == name) {
            BOOST_TEST_REQUIRE(row.parse(p, text), name << " " << text);
        }
    }
    try {
        p.validate();
    } catch (const ParameterError& e) {
        return e.name();
    }
    return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pour_parameters_table)

BOOST_AUTO_TEST_CASE(rows_are_unique_and_read_back_their_defaults) {
    std::set<std::string> names;
    const PourParams defaults;
    for (const PourParameter& row : pour_parameters()) {
        BOOST_TEST(names.insert(row.name).second, row.name);
        BOOST_TEST(row.default_text == row.format(defaults), row.name);
        PourParams p;
        BOOST_TEST(row.parse(p, row.default_text), row.name);
        BOOST_TEST(row.format(p) == row.default_text, row.name);
    }
    BOOST_CHECK_NO_THROW(valid().validate());  // the defaults with a count are valid
}

BOOST_AUTO_TEST_CASE(validate_refuses_each_rule_at_its_edge) {
    BOOST_TEST(refused_after("friction", "-0.001") == "friction");
    BOOST_TEST(refused_after("friction", "10") == "");
    BOOST_TEST(refused_after("restitution", "1") == "restitution");
    BOOST_TEST(refused_after("youngs_modulus", "5e6") == "youngs_modulus");
    BOOST_TEST(refused_after("youngs_modulus", "5.000001e6") == "");
    BOOST_TEST(refused_after("density", "inf") == "density");
    BOOST_TEST(refused_after("cloud_fraction", "0.36") == "cloud_fraction");
    BOOST_TEST(refused_after("check_time", "1e-300") == "max_time");  // 10^6 checks at most
    BOOST_TEST(refused_after("ranks", "65") == "ranks");
    BOOST_TEST(refused_after("processors", "2,1,1") == "processors");  // ranks is 1
    BOOST_TEST(refused_after("count", "0") == "count");
}

BOOST_AUTO_TEST_CASE(header_keys_carry_their_units) {
    PourParams p = valid();
    Metadata m;
    for (const char* group : {"count", "identity", "start", "material", "numerics", "parallel"}) {
        record_pour_parameters(p, group, m);
    }
    BOOST_TEST(m.get("youngs_modulus_pa").value_or("") == "1e+09");
    BOOST_TEST(m.get("density_kg_m3").value_or("") == "2500");
    BOOST_TEST(m.get("check_time_s").value_or("") == "0.02");
    BOOST_TEST(m.get("cloud_fraction").has_value());  // a cloud start
    BOOST_TEST(!m.get("start_jitter").has_value());
    BOOST_TEST(!m.get("max_time").has_value());  // recorded as the step cap
    BOOST_TEST(!m.get("youngs_modulus").has_value());
}

BOOST_AUTO_TEST_SUITE_END()
