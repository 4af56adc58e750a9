#include "dynamics/model.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <fmt/format.h>

namespace gaitopt::dynamics {
namespace {

/// Mass of the links after index i in chain order (sum_{k>i} m_k of eq. 2.8).
double massBeyond(const std::vector<Link>& links, int i) {
  double m = 0;
  for (size_t k = static_cast<size_t>(i) + 1; k < links.size(); ++k) m += links[k].mass;
  return m;
}

bool mirrors(const Link& stance, const Link& swing) {
  auto close = [](double x, double y) { return std::abs(x - y) <= 1e-9 * (1 + std::abs(x)); };
  return close(stance.mass, swing.mass) && close(stance.inertia, swing.inertia) &&
         close(stance.length, swing.length) && close(stance.com, swing.length - swing.com);
}

}  // namespace

Model::Model(std::string name, std::vector<Link> links, std::vector<Joint> joints, double gravity,
             double friction, Foot foot, double slope)
    : name_(std::move(name)),
      links_(std::move(links)),
      joints_(std::move(joints)),
      gravity_(gravity),
      friction_(friction),
      foot_(foot),
      slope_(slope),
      gravity_acc_(-gravity * std::sin(slope), -gravity * std::cos(slope)) {
  if (!(std::isfinite(slope) && std::abs(slope) < std::numbers::pi / 2))
    throw std::invalid_argument(
        fmt::format("slope {} rad: expected a finite inclination with |slope| < pi/2", slope));
  checkStructure();
  precompute();
}

void Model::checkStructure() const {
  const int n = nLinks();
  if (n < 2 || n > kMaxLinks)
    throw std::invalid_argument(fmt::format("a robot needs 2 to {} links, got {}", kMaxLinks, n));
  if (static_cast<int>(joints_.size()) != n)
    throw std::invalid_argument(
        fmt::format("a chain of {} links has {} joints (ankle + one per link pair), got {}", n, n,
                    joints_.size()));
  int branches = 0;
  for (const auto& l : links_) branches += l.continues ? 0 : 1;
  const int legs = n - branches;
  if (branches > 1 || legs % 2 != 0)
    throw std::invalid_argument(
        "links must form two legs of equal length plus at most one terminal branch (torso)");
  const int k = legs / 2;
  if (branches == 1 && links_[static_cast<size_t>(k)].continues)
    throw std::invalid_argument(fmt::format(
        "the torso (continues: false) must be link {} of {}, between the two legs", k + 1, n));
  for (int i = 0; i < k; ++i) {
    const auto& stance = links_[static_cast<size_t>(i)];
    const auto& swing = links_[static_cast<size_t>(n - 1 - i)];
    if (!mirrors(stance, swing))
      throw std::invalid_argument(fmt::format(
          "legs must be identical for relabelling: link '{}' must mirror '{}' (same mass, inertia "
          "and length, com = length - com)",
          swing.name, stance.name));
  }
}

void Model::precompute() {
  const int n = nLinks();
  leg_links_ = (n - (n % 2)) / 2;
  for (int i = 0; i < n; ++i)
    if (!links_[static_cast<size_t>(i)].continues) torso_ = i;

  // Mu (2.8a, 2.8c) with the corrected gravity sign applied where G is formed.
  p_ = MatD::Zero(n, n);
  g_ = VecD::Zero(n);
  for (int i = 0; i < n; ++i) {
    const Link& li = links_[static_cast<size_t>(i)];
    p_(i, i) = li.inertia + li.mass * li.com * li.com +
               li.a() * massBeyond(links_, i) * li.length * li.length;
    g_(i) = (li.mass * li.com + li.a() * massBeyond(links_, i) * li.length) * gravity_;
    for (int j = i + 1; j < n; ++j) {
      const Link& lj = links_[static_cast<size_t>(j)];
      p_(i, j) = li.a() * lj.mass * lj.com * li.length +
                 li.a() * lj.a() * massBeyond(links_, j) * li.length * lj.length;
      p_(j, i) = p_(i, j);
    }
  }

  // Chain-point weights (Mu 2.1-2.2, 2.13).
  total_mass_ = 0;
  tip_ = hip_ = total_com_ = ChainPoint::Zero(n);
  com_.assign(static_cast<size_t>(n), ChainPoint::Zero(n));
  joint_.assign(static_cast<size_t>(n), ChainPoint::Zero(n));
  for (int i = 0; i < n; ++i) {
    const Link& li = links_[static_cast<size_t>(i)];
    tip_(i) = li.a() * li.length;
    if (i < leg_links_) hip_(i) = li.length;
    for (int j = 0; j < i; ++j) joint_[static_cast<size_t>(i)](j) = tip_(j);
    com_[static_cast<size_t>(i)] = joint_[static_cast<size_t>(i)];
    com_[static_cast<size_t>(i)](i) = li.com;
    total_com_ += li.mass * com_[static_cast<size_t>(i)];
    total_mass_ += li.mass;
  }
  total_com_ /= total_mass_;
}

void requireKneedLegs(const Model& model, std::string_view user) {
  if (model.legLinks() != 2)
    throw std::invalid_argument(
        fmt::format("{} needs legs of two links (thigh and shank); robot '{}' has {} per leg", user,
                    model.name(), model.legLinks()));
}

}  // namespace gaitopt::dynamics
