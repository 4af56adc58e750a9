#include "ocp/solve/kkt/symmetric_pattern.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace gaitopt::ocp::kkt {

SymmetricPattern SymmetricPattern::fromPardiso(int n, const int* ia, const int* ja) {
  std::vector<int> outer(ia, ia + n + 1);
  for (int& start : outer) --start;
  std::vector<int> inner(ja, ja + outer[n]);
  for (int& row : inner) --row;
  return fromLowerCsc(n, std::move(outer), std::move(inner));
}

SymmetricPattern SymmetricPattern::fromLowerCsc(int n, std::vector<int> outer,
                                                std::vector<int> inner) {
  SymmetricPattern p{n, std::move(outer), std::move(inner), std::vector<int>(n, -1)};
  for (int j = 0; j < n; ++j) {
    for (int k = p.outer[j]; k < p.outer[j + 1]; ++k) {
      if (p.inner[k] < j || p.inner[k] >= n)
        throw std::invalid_argument("KKT pattern: entry outside the lower triangle in column " +
                                    std::to_string(j));
      if (p.inner[k] == j) p.diagonal[j] = k;
    }
    if (p.diagonal[j] < 0)
      throw std::invalid_argument("KKT pattern: column " + std::to_string(j) +
                                  " has no diagonal entry (Pardiso's format stores every one)");
  }
  return p;
}

}  // namespace gaitopt::ocp::kkt
