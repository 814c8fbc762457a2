#pragma once
/// @file world.hpp
/// The processes of one batch. Started by an MPI launcher (`mpirun -np K`, `srun` — seen
/// from the variables they set: OMPI_COMM_WORLD_SIZE, PMI_SIZE, PMIX_RANK), the batch is
/// an MPI program of K ranks; started alone it is one process and MPI is never
/// initialised (so a plain run pays nothing for it).

#include <cstddef>
#include <string>
#include <vector>

namespace sgmp::batch {

/// Whether an MPI launcher started this process (OMPI_COMM_WORLD_SIZE, PMI_SIZE or
/// PMIX_RANK set).
bool launched_by_mpi();

/// Without MPI (SGMP_WITH_MPI=OFF) the world is this one process; constructing it in a
/// process an MPI launcher started throws std::runtime_error (every rank would make every
/// pack).
class World {
  public:
    World();  // initialises MPI when launched by an MPI launcher
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    [[nodiscard]] std::size_t rank() const { return rank_; }
    [[nodiscard]] std::size_t size() const { return size_; }

    /// True on every rank when `ok` is true on every rank (a collective; a barrier).
    bool all(bool ok) const;

    /// Every rank's `text`, in rank order, at rank 0 (empty elsewhere). A collective.
    std::vector<std::string> gather(const std::string& text) const;

    /// Stops every rank with `status` (after a failure on one rank), first removing this
    /// rank's registered temporaries (interrupt.hpp), the summary's lock file among them.
    [[noreturn]] void abort(int status) const;

  private:
    bool mpi_ = false;
    std::size_t rank_ = 0;
    std::size_t size_ = 1;
};

}  // namespace sgmp::batch
