#include "sgmp/batch/world.hpp"

#include <mpi.h>

#include <cstdlib>
#include <numeric>

#include "sgmp/pack/interrupt.hpp"

namespace sgmp::batch {

World::World() {
    if (!launched_by_mpi()) {
        return;
    }
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (initialised == 0) {
        MPI_Init(nullptr, nullptr);
    }
    mpi_ = true;
    int rank = 0;
    int size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    rank_ = static_cast<std::size_t>(rank);
    size_ = static_cast<std::size_t>(size);
}

World::~World() {
    if (mpi_) {
        MPI_Finalize();
    }
}

bool World::all(bool ok) const {
    if (!mpi_) {
        return ok;
    }
    int mine = ok ? 1 : 0;
    int every = 0;
    MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return every == 1;
}

std::vector<std::string> World::gather(const std::string& text) const {
    if (!mpi_) {
        return {text};
    }
    const int length = static_cast<int>(text.size());
    std::vector<int> lengths(size_);
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> offsets(size_, 0);
    std::string all;
    if (rank_ == 0) {
        std::exclusive_scan(lengths.begin(), lengths.end(), offsets.begin(), 0);
        all.resize(static_cast<std::size_t>(offsets.back() + lengths.back()));
    }
    MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
                0, MPI_COMM_WORLD);
    std::vector<std::string> texts;
    if (rank_ == 0) {
        for (std::size_t r = 0; r < size_; ++r) {
            texts.push_back(all.substr(static_cast<std::size_t>(offsets[r]),
                                       static_cast<std::size_t>(lengths[r])));
        }
    }
    return texts;
}

void World::abort(int status) const {
    // std::exit and MPI_Abort skip the destructors of the caller's locals: the summary's
    // lock file and the temporaries of jobs still running are removed here, as an
    // interrupt removes them.
    remove_registered_temporaries();
    if (mpi_) {
        MPI_Abort(MPI_COMM_WORLD, status);
    }
    std::exit(status);
}

}  // namespace sgmp::batch
