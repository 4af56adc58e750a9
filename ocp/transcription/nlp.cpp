#include "ocp/transcription/nlp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace gaitopt::ocp {
namespace {

Eigen::VectorXd append(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  Eigen::VectorXd out(a.size() + b.size());
  out << a, b;
  return out;
}

/// The entry of `value` farthest outside [lower, upper]: its index and distance (0 when all
/// are within). A NaN entry counts as infinitely far.
std::pair<int, double> farthestOutside(const Eigen::VectorXd& value, const Eigen::VectorXd& lower,
                                       const Eigen::VectorXd& upper) {
  std::pair<int, double> worst{-1, 0.0};
  for (Eigen::Index i = 0; i < value.size(); ++i) {
    const double v = value(i);
    const double d = std::isnan(v) ? std::numeric_limits<double>::infinity()
                                   : std::max({0.0, lower(i) - v, v - upper(i)});
    if (d > worst.second) worst = {static_cast<int>(i), d};
  }
  return worst;
}

/// The entry of `value` farthest outside [lower, upper], placed by `locate` (index -> Violation)
/// and given its value, bounds and distance; empty when every entry is within.
template <class Locate>
Violation worstOf(const Eigen::VectorXd& value, const Eigen::VectorXd& lower,
                  const Eigen::VectorXd& upper, Locate locate) {
  const auto [i, amount] = farthestOutside(value, lower, upper);
  if (i < 0) return {};
  Violation v = locate(i);
  v.amount = amount;
  v.value = value(i);
  v.lower = lower(i);
  v.upper = upper(i);
  return v;
}

}  // namespace

void SparsityPattern::record(const Triplets& entries) {
  // Sorting the entries by position groups the duplicates: O(N log N) with one allocation,
  // where a map of positions allocated a node per entry (most of the recording time of the
  // five-link NLP, whose point blocks repeat the positions they share). The slots keep the
  // order of first appearance: MUMPS's ordering, and so the iterates, depend on it.
  const size_t n = entries.size();
  auto key = [&entries](size_t k) { return std::make_pair(entries[k].row(), entries[k].col()); };
  std::vector<size_t> order(n);
  for (size_t k = 0; k < n; ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&key](size_t a, size_t b) { return key(a) < key(b); });
  std::vector<size_t> first(n);  // the first entry at the position of entry k
  for (size_t i = 0; i < n; ++i)
    first[order[i]] = i > 0 && key(order[i]) == key(order[i - 1]) ? first[order[i - 1]] : order[i];
  rows_.clear();
  cols_.clear();
  slot_.assign(n, 0);
  for (size_t k = 0; k < n; ++k) {
    if (first[k] == k) {
      slot_[k] = static_cast<int>(rows_.size());
      rows_.push_back(entries[k].row());
      cols_.push_back(entries[k].col());
    } else {
      slot_[k] = slot_[first[k]];
    }
  }
}

void SparsityPattern::accumulate(const Triplets& entries, double* values) const {
  if (entries.size() != slot_.size())
    throw std::logic_error(fmt::format("sparsity contract broken: {} entries emitted, {} recorded",
                                       entries.size(), slot_.size()));
  std::fill(values, values + rows_.size(), 0.0);
  for (size_t k = 0; k < entries.size(); ++k) values[slot_[k]] += entries[k].value();
}

VariableBlock Nlp::addVariables(const std::string& name, int size, const Eigen::VectorXd& lower,
                                const Eigen::VectorXd& upper, const Eigen::VectorXd& initial,
                                const std::string& phase, int point_size) {
  if (lower.size() != size || upper.size() != size || initial.size() != size)
    throw std::invalid_argument(
        fmt::format("variable block '{}': bounds and guess need {} entries", name, size));
  const VariableBlock block{name, variables(), size, phase, point_size};
  x0_ = append(x0_, initial);
  xl_ = append(xl_, lower);
  xu_ = append(xu_, upper);
  blocks_.push_back(block);
  return block;
}

void Nlp::addConstraint(std::unique_ptr<ConstraintSet> set) {
  sets_.push_back(std::move(set));
}
void Nlp::addCost(std::unique_ptr<CostTerm> term) {
  costs_.push_back(std::move(term));
}

int Nlp::constraints() const {
  int m = 0;
  for (const auto& s : sets_) m += s->rows();
  return m;
}

Eigen::VectorXd Nlp::constraintLower() const {
  Eigen::VectorXd out(0);
  for (const auto& s : sets_) out = append(out, s->lowerBounds());
  return out;
}

Eigen::VectorXd Nlp::constraintUpper() const {
  Eigen::VectorXd out(0);
  for (const auto& s : sets_) out = append(out, s->upperBounds());
  return out;
}

double Nlp::cost(const Eigen::VectorXd& x) const {
  double f = 0;
  for (const auto& c : costs_) f += c->value(x);
  return f;
}

Eigen::VectorXd Nlp::costGradient(const Eigen::VectorXd& x) const {
  Eigen::VectorXd grad = Eigen::VectorXd::Zero(x.size());
  for (const auto& c : costs_) c->gradient(x, grad);
  return grad;
}

Eigen::VectorXd Nlp::constraintValues(const Eigen::VectorXd& x) const {
  Eigen::VectorXd g(constraints());
  int row = 0;
  for (const auto& s : sets_) {
    s->values(x, g.segment(row, s->rows()));
    row += s->rows();
  }
  return g;
}

void Nlp::jacobianTriplets(const Eigen::VectorXd& x, Triplets& out) const {
  out.clear();
  int row = 0;
  for (const auto& s : sets_) {
    const size_t first = out.size();
    s->jacobian(x, out);  // the set's own rows, moved to its place below
    for (size_t k = first; k < out.size(); ++k)
      out[k] = Eigen::Triplet<double>(row + out[k].row(), out[k].col(), out[k].value());
    row += s->rows();
  }
}

Triplets Nlp::jacobianTriplets(const Eigen::VectorXd& x) const {
  Triplets all;
  jacobianTriplets(x, all);
  return all;
}

void Nlp::hessianTriplets(const Eigen::VectorXd& x, double obj_factor,
                          const Eigen::VectorXd& lambda, Triplets& out) const {
  out.clear();
  for (const auto& c : costs_) c->hessian(x, obj_factor, out);
  int row = 0;
  for (const auto& s : sets_) {
    s->hessian(x, lambda.segment(row, s->rows()), out);
    row += s->rows();
  }
}

Triplets Nlp::hessianTriplets(const Eigen::VectorXd& x, double obj_factor,
                              const Eigen::VectorXd& lambda) const {
  Triplets all;
  hessianTriplets(x, obj_factor, lambda, all);
  return all;
}

Violation Nlp::locateConstraintRow(int row) const {
  int first = 0;
  for (const auto& s : sets_) {
    const int r = row - first;
    if (r < s->rows())
      return {
          .name = s->name(), .phase = s->phase(), .part = "row", .index = r, .node = s->nodeOf(r)};
    first += s->rows();
  }
  throw std::logic_error("constraint row beyond the last set");
}

Violation Nlp::locateVariable(int i) const {
  for (const auto& b : blocks_) {
    if (i >= b.offset + b.size) continue;
    const int element = i - b.offset;
    const GridNode node = b.point_size > 0
                              ? GridNode{"point", element / b.point_size, element % b.point_size}
                              : GridNode{};
    return {.name = b.name, .phase = b.phase, .part = "element", .index = element, .node = node};
  }
  throw std::logic_error("variable beyond the last block");
}

Violation Nlp::worstConstraint(const Eigen::VectorXd& x) const {
  return worstOf(constraintValues(x), constraintLower(), constraintUpper(),
                 [this](int row) { return locateConstraintRow(row); });
}

Violation Nlp::worstBound(const Eigen::VectorXd& x) const {
  return worstOf(x, xl_, xu_, [this](int i) { return locateVariable(i); });
}

std::string whereOf(const Violation& v) {
  const std::string where = v.node.index < 0 ? fmt::format("{}, {} {}", v.phase, v.part, v.index)
                                             : fmt::format("{}, {} {}, {} {}", v.phase, v.node.kind,
                                                           v.node.index, v.part, v.node.entry);
  return fmt::format("{} ({})", v.name, where);
}

std::string describe(const Violation& v) {
  if (v.name.empty()) return "none";
  return fmt::format("{}: {:.4g} outside [{:.4g}, {:.4g}] by {:.3g}", whereOf(v), v.value, v.lower,
                     v.upper, v.amount);
}

}  // namespace gaitopt::ocp
