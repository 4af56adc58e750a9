// Compiled into every program of another project that links gaitopt's installed package
// (gaitoptConfig.cmake adds it to gaitopt::io's users): it names the package's share/gaitopt,
// found from where the package's config file lies, so the shipped configs are read from the
// installed tree wherever it was installed or moved (io/data_dir.hpp), not from the source tree
// it was built from.
#include "io/data_dir.hpp"

namespace {

const bool kDataDirNamed = [] {
  gaitopt::io::useInstalledDataDir(GAITOPT_PACKAGE_DATA_DIR);
  return true;
}();

}  // namespace
