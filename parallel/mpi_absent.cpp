// The MPI entry points of a build without MPI (-DGAITOPT_MPI=OFF): the library command then
// tells a user who launched it under mpirun to rebuild, instead of letting every rank build
// the whole library on its own.
#include <stdexcept>

#include "parallel/mpi_executor.hpp"

namespace gaitopt::parallel {

bool builtWithMpi() {
  return false;
}

MpiSession::MpiSession() {
  throw std::runtime_error("gaitopt was built without MPI: reconfigure with -DGAITOPT_MPI=ON");
}

MpiSession::~MpiSession() = default;

std::unique_ptr<Executor> makeMpiExecutor(const MpiSession&, std::unique_ptr<Executor>) {
  throw std::runtime_error("gaitopt was built without MPI");
}

void serveMpiJobs(const MpiSession&, Executor&) {
  throw std::runtime_error("gaitopt was built without MPI");
}

}  // namespace gaitopt::parallel
