#pragma once

#include <string>
#include <vector>

namespace tendril::sweeps {

// The part of a sweep one process trains when several train it at once: process `rank` of
// `ranks` takes the runs i with i mod ranks == rank (round robin, so every process gets runs
// from every part of the grid and the shares differ in size by at most one run).
struct SweepShare {
  int rank = 0;
  int ranks = 1;
  std::string source;  // where rank and size came from, for messages ("OMPI_COMM_WORLD_*")

  // The rank and size an MPI launcher or Slurm gives its processes through the environment:
  // OpenMPI's OMPI_COMM_WORLD_RANK/SIZE, MPICH's and Intel MPI's PMI_RANK/PMI_SIZE, srun's
  // SLURM_PROCID/SLURM_NTASKS, the first pair present; rank 0 of 1 when there is none. A
  // malformed value raises Error naming the variable.
  static SweepShare from_environment();

  // The indices of the runs of this share, ascending, out of `run_count`.
  std::vector<int> runs(int run_count) const;
};

}  // namespace tendril::sweeps
