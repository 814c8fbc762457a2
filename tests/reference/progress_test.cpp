// Following LIGGGHTS' output: the banner, errors and the SGMP- marker lines.
#include <boost/test/unit_test.hpp>

#include "sgmp/reference/progress.hpp"

using namespace sgmp::reference;

BOOST_AUTO_TEST_SUITE(progress)

BOOST_AUTO_TEST_CASE(markers_describe_the_pour) {
    PourLog log;
    BOOST_TEST(!log.take("LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, compiled 2023-01-01 by x)"));
    BOOST_TEST(log.liggghts_version == "3.8.0");
    log.take(
        "SGMP-PARAMETERS timestep 0.0001 rayleigh_time 0.001 fall_steps 600 check_steps 200 "
        "step_cap 300000");
    BOOST_TEST(*log.timestep == 0.0001);
    BOOST_TEST(*log.step_cap == 300000);
    log.take("SGMP-INSERTED 150");
    BOOST_TEST(*log.inserted == 150);

    BOOST_TEST(log.take("SGMP-FALL 31 600 0.5"));
    BOOST_TEST((log.progress.phase == PourPhase::falling));
    BOOST_TEST(log.progress.step == 31);
    BOOST_TEST(log.progress.phase_steps == 600);

    BOOST_TEST(log.take("SGMP-SETTLE 800 2.5e-05 1e-06"));
    BOOST_TEST((log.progress.phase == PourPhase::settling));
    BOOST_TEST(log.progress.ke_ratio == 2.5e-05);
    BOOST_TEST(log.progress.threshold == 1e-06);
    BOOST_TEST(log.progress.phase_steps == 300000);

    BOOST_TEST(!log.settled.has_value());
    log.take("SGMP-RESULT settled 1200 5e-07");
    BOOST_TEST(*log.settled);
    BOOST_TEST(log.steps == 1200);
    BOOST_TEST(!log.done);
    BOOST_TEST(log.take("SGMP-DONE"));
    BOOST_TEST(log.done);
}

BOOST_AUTO_TEST_CASE(the_first_error_line_is_kept) {
    PourLog log;
    log.take("ERROR: Illegal fix wall/gran command (./src/fix_wall_gran.cpp:123)");
    log.take("ERROR: a later one");
    BOOST_TEST(log.first_error ==
               "ERROR: Illegal fix wall/gran command (./src/fix_wall_gran.cpp:123)");
    PourLog unsettled;
    unsettled.take("SGMP-RESULT unsettled 5000 0.01");
    BOOST_TEST(!*unsettled.settled);
}

BOOST_AUTO_TEST_CASE(ordinary_output_changes_nothing) {
    PourLog log;
    BOOST_TEST(!log.take("    1000     1002      4275.1261     0.60112532    0.059511477"));
    BOOST_TEST(!log.take(""));
    BOOST_TEST(!log.take("SGMP-FALL"));  // too short: ignored, not misread
    BOOST_TEST((log.progress.phase == PourPhase::starting));
}

BOOST_AUTO_TEST_SUITE_END()
