#pragma once
/// @file pardiso_interface.hpp
/// The name under which Ipopt's Pardiso loader finds gaitopt's KKT solver (the soname of the
/// gaitopt_kkt library, pardiso_interface.cpp).

namespace gaitopt::ocp::kkt {

extern const char* const kLibraryName;

}  // namespace gaitopt::ocp::kkt
