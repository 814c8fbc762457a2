// libFuzzer target: read_pack_file on a file of the input's bytes (gzip detection and
// decompression, then format detection between extended XYZ and dump custom).
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "sgmp/pack/input_error.hpp"
#include "sgmp/pack/pack_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const int fd = ::memfd_create("fuzz-pack", 0);
    if (fd < 0) {
        std::abort();
    }
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, data, size, 0) != static_cast<ssize_t>(size)) {
        std::abort();
    }
    try {
        (void)sgmp::read_pack_file("/proc/self/fd/" + std::to_string(fd));
    } catch (const sgmp::InputError&) {
    }
    return 0;
}
