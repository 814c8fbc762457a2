// The world of a build without MPI (SGMP_WITH_MPI=OFF): this one process.
#include <cstdlib>
#include <stdexcept>

#include "sgmp/batch/world.hpp"
#include "sgmp/pack/interrupt.hpp"

namespace sgmp::batch {

World::World() {
    if (launched_by_mpi()) {
        throw std::runtime_error(
            "this sgmp was built without MPI (SGMP_WITH_MPI=OFF): run one process, or split "
            "the batch with --shard I/N");
    }
}

World::~World() = default;

bool World::all(bool ok) const {
    return ok;
}

std::vector<std::string> World::gather(const std::string& text) const {
    return {text};
}

void World::abort(int status) const {
    remove_registered_temporaries();
    std::exit(status);
}

}  // namespace sgmp::batch
