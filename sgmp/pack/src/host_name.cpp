#include "sgmp/pack/host_name.hpp"

#include <unistd.h>

namespace sgmp {

const std::string& host_name() {
    static const std::string name = [] {
        char buffer[256] = {};
        if (::gethostname(buffer, sizeof buffer - 1) != 0 || buffer[0] == '\0') {
            return std::string("localhost");
        }
        return std::string(buffer);
    }();
    return name;
}

}  // namespace sgmp
