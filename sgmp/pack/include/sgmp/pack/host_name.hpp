#pragma once
/// @file host_name.hpp
/// The name of the host this process runs on (the node, on a cluster): what temporaries
/// and output locks record so that another host's work is told apart from this one's.

#include <string>

namespace sgmp {

/// gethostname(2), read once; "localhost" when it cannot be read.
const std::string& host_name();

}  // namespace sgmp
