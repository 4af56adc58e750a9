// walkDart in a build with DART: loads the DART plant's module (dart_walk.hpp says why it is one)
// at the first call and walks through it.
#include <dlfcn.h>

#include <stdexcept>
#include <string>

#include "sim/contact/dart_walk.hpp"

namespace gaitopt::sim {

namespace {

// The module sits beside libpardiso.so (sim/CMakeLists.txt, cmake/Install.cmake), on the run
// path of every program that links gaitopt's solver: the tool, the tests, the Python module and
// programs built against the installed package. Kept loaded for the life of the process.
DartWalk loadDartModule() {
  void* module = dlopen(kDartModuleName, RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr)
    throw std::runtime_error(std::string("the dart ground: cannot load ") + kDartModuleName +
                             " (it is installed beside libpardiso.so; LD_LIBRARY_PATH may name "
                             "its folder): " +
                             dlerror());
  using Entry = DartWalk (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(module, kDartModuleEntry));
  if (entry == nullptr)
    throw std::runtime_error(std::string("the dart ground: ") + kDartModuleName + " has no " +
                             kDartModuleEntry);
  return entry();
}

}  // namespace

WalkResult walkDart(const dynamics::Model& plant, const Controller& controller,
                    const Reference& ref, const DartGround& ground, const WalkPlan& plan,
                    const WalkLog& log, const VecD& theta0, const VecD& dtheta0) {
  static const DartWalk walk = loadDartModule();
  return walk(plant, controller, ref, ground, plan, log, theta0, dtheta0);
}

}  // namespace gaitopt::sim
