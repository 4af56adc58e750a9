#pragma once
/// @file symmetric_pattern.hpp
/// The sparsity of a symmetric matrix stored by its lower triangle, column by column (0-based
/// CSC, every diagonal entry present). Ipopt hands Pardiso the upper triangle row by row, 1-based
/// (IpTripletToCSRConverter.hpp): the same arrays read as the lower triangle by columns.
#include <vector>

namespace gaitopt::ocp::kkt {

struct SymmetricPattern {
  int n = 0;
  std::vector<int> outer;     ///< n + 1 column starts
  std::vector<int> inner;     ///< row of each stored entry, >= its column
  std::vector<int> diagonal;  ///< position of each column's diagonal entry in `inner`

  /// From Pardiso's 1-based upper-triangle CSR (ia, ja); refuses a missing diagonal entry.
  static SymmetricPattern fromPardiso(int n, const int* ia, const int* ja);
  /// From 0-based lower-triangle CSC arrays; refuses a missing diagonal entry.
  static SymmetricPattern fromLowerCsc(int n, std::vector<int> outer, std::vector<int> inner);
  int nonZeros() const { return outer.empty() ? 0 : outer.back(); }
};

}  // namespace gaitopt::ocp::kkt
