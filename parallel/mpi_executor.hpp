#pragma once
/// @file mpi_executor.hpp
/// The executor across machines: the ranks of an MPI job (`mpirun -np N gaitopt ...`). Rank 0
/// runs the scheduler and a local executor (worker processes); every other rank serves jobs on
/// a local executor of its own, of the same size. Rank 0 hands a job to whichever slot is free, so
/// ranks that drew long jobs simply take fewer (dynamic load balancing, no static partition). Jobs
/// and results travel as text; files they name must be on a file system every rank sees (as on a
/// cluster's shared home or scratch). Built only with -DGAITOPT_MPI=ON (Debian's OpenMPI).
#include <memory>

#include "parallel/executor.hpp"

namespace gaitopt::parallel {

/// Whether this process was started by an MPI launcher (mpirun/mpiexec of OpenMPI or MPICH, or
/// a PMIx launcher such as srun), read from the environment the launcher sets.
bool launchedByMpi();

/// Whether this build has MPI support.
bool builtWithMpi();

/// MPI_Init_thread (funnelled: only the calling thread talks to MPI) and MPI_Finalize.
/// @throws std::runtime_error without MPI support or when MPI cannot start.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

/// Rank 0's executor: the slots of `local` plus as many on each other rank. Its destructor
/// tells the other ranks to stop.
std::unique_ptr<Executor> makeMpiExecutor(const MpiSession& session,
                                          std::unique_ptr<Executor> local);

/// Ranks > 0: serves rank 0's jobs on `local` until rank 0 says stop.
void serveMpiJobs(const MpiSession& session, Executor& local);

}  // namespace gaitopt::parallel
