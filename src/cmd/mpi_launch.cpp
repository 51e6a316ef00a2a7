// SPDX-License-Identifier: Apache-2.0
#include "cmd/mpi_launch.h"

#include <cstdlib>

namespace toroid::cmd {

namespace {

// The rank variables of Open MPI, PMIx (Open MPI 5, Slurm) and MPICH's PMI.
constexpr const char* kRankVariables[] = {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"};

}  // namespace

bool launched_by_mpi() {
  for (const char* v : kRankVariables)
    if (std::getenv(v)) return true;
  return false;
}

int launcher_rank() {
  for (const char* v : kRankVariables)
    if (const char* r = std::getenv(v)) return std::atoi(r);
  return 0;
}

}  // namespace toroid::cmd
