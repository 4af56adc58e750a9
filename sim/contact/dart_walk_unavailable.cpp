// The DART plant in a build without DART (GAITOPT_DART=OFF): it says so.
#include <stdexcept>

#include "sim/contact/dart_walk.hpp"

namespace gaitopt::sim {

WalkResult walkDart(const dynamics::Model& /*plant*/, const Controller& /*controller*/,
                    const Reference& /*ref*/, const DartGround& /*ground*/,
                    const WalkPlan& /*plan*/, const WalkLog& /*log*/, const VecD& /*theta0*/,
                    const VecD& /*dtheta0*/) {
  throw std::invalid_argument(
      "the dart ground needs a build with DART (apt-get install libdart-dev "
      "libdart-utils-urdf-dev; cmake -DGAITOPT_DART=ON)");
}

}  // namespace gaitopt::sim
