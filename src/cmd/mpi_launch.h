// SPDX-License-Identifier: Apache-2.0
// Whether this process was started by an MPI launcher (mpirun, mpiexec,
// srun), read from the environment the launcher sets, so that a plain
// `toroid render` never initialises MPI.
#pragma once

namespace toroid::cmd {

// True when an MPI launcher started this process.
bool launched_by_mpi();

// This process's rank as the launcher set it; 0 when not launched by MPI.
int launcher_rank();

}  // namespace toroid::cmd
