#include <cstdlib>

#include "parallel/mpi_executor.hpp"

namespace gaitopt::parallel {

bool launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

}  // namespace gaitopt::parallel
