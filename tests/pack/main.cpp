#define BOOST_TEST_MODULE pack
#include <boost/test/unit_test.hpp>
