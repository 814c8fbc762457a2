// Makes a 150-sphere pack through the installed engine and writes it: the same bytes as
// `sgmp pack --count 150 --arrangement loose-random --seed 3`.
#include <iostream>

#include "sgmp/engine/make_pack.hpp"
#include "sgmp/pack/pack_file.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: downstream OUT.xyz\n";
        return 2;
    }
    sgmp::engine::PackRequest request;
    request.count = 150;
    request.arrangement = sgmp::engine::Arrangement::LooseRandom;
    request.seed = 3;
    sgmp::write_pack_file(argv[1], sgmp::engine::make_pack(request), false);
    return 0;
}
