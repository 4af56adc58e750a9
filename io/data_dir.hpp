#pragma once
/// @file data_dir.hpp
/// Where gaitopt's shipped files are found at run time: the plot scripts (plots/) and the
/// default configs (configs/: robots, grounds, ...). An installed tool reads them from
/// PREFIX/share/gaitopt, so it keeps working when the source tree it was built from is gone; a
/// tool run from its build tree reads the source tree, so an edit there is seen at once.
#include <string>

namespace gaitopt::io {

/// The folder holding configs/ and plots/, the first of:
/// 1. $GAITOPT_DATA_DIR, when set;
/// 2. PREFIX/share/gaitopt, when the running program is PREFIX/bin/NAME or the running code is the
///    Python module PREFIX/lib/python3/dist-packages/gaitopt.so, and that folder exists (an
///    installed tree, wherever it was moved);
/// 3. the share/gaitopt of the installed package a program of another project was built against
///    (useInstalledDataDir), wherever that package was installed or moved to;
/// 4. the source tree the library was built from, when it still exists;
/// 5. the install prefix's share/gaitopt chosen at configure time.
std::string dataDir();

/// Names the share/gaitopt of the installed package: called before main by a file the package
/// compiles into each program that links it (cmake/installed_data_dir.cpp).
void useInstalledDataDir(const std::string& dir);

/// dataDir() / `relative` (e.g. "configs/grounds/rigid.yaml").
std::string dataFile(const std::string& relative);

/// A file the docs name by its shipped path (e.g. "configs/robots/NAME.yaml"): `relative` under
/// the working directory when it is there (a user's own), else dataFile(relative) when that is
/// there, else empty.
std::string localOrShipped(const std::string& relative);

/// A file path as the docs spell it: one under configs/ that the working directory lacks is the
/// shipped file (localOrShipped); any other path, or one found nowhere, is `path` itself (its
/// loader then names it as missing).
std::string shippedIfMissing(const std::string& path);

}  // namespace gaitopt::io
