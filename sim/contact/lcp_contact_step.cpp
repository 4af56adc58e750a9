#include "sim/contact/lcp_contact_step.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>

namespace gaitopt::sim {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("lcpContactStep: " + what);
}

void validate(const Eigen::MatrixXd& mass, const Eigen::VectorXd& force,
              const Eigen::VectorXd& velocity, double step,
              const std::vector<ContactRows>& contacts) {
  const Eigen::Index nq = velocity.size();
  require(mass.rows() == nq && mass.cols() == nq && force.size() == nq,
          "mass must be nq x nq and force nq, with nq = velocity.size() = " + std::to_string(nq));
  require(mass.allFinite() && force.allFinite() && velocity.allFinite(),
          "mass, force and velocity must be finite");
  require(std::isfinite(step) && step > 0, "step must be positive and finite");
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactRows& c = contacts[i];
    const std::string name = "contact " + std::to_string(i) + ": ";
    require(c.normal.size() == nq && c.tangent.size() == nq, name + "rows must have nq columns");
    require(c.normal.allFinite() && c.tangent.allFinite() && std::isfinite(c.gap),
            name + "rows and gap must be finite");
    require(std::isfinite(c.friction) && c.friction >= 0, name + "friction must be >= 0");
  }
}

/// G = [N^T, T^T, -T^T] (nq x 3nc): the generalised impulse per unit p_n, beta+, beta-.
Eigen::MatrixXd impulseDirections(const std::vector<ContactRows>& contacts, Eigen::Index nq) {
  const Eigen::Index nc = static_cast<Eigen::Index>(contacts.size());
  Eigen::MatrixXd g(nq, 3 * nc);
  for (Eigen::Index i = 0; i < nc; ++i) {
    g.col(i) = contacts[i].normal.transpose();
    g.col(nc + i) = contacts[i].tangent.transpose();
    g.col(2 * nc + i) = -contacts[i].tangent.transpose();
  }
  return g;
}

struct Lcp {
  Eigen::MatrixXd a;
  Eigen::VectorXd b;
};

/// The LCP in z = (p_n, beta+, beta-, lambda), 4 nc unknowns: w = A z + b with
///   A = [G^T M^-1 G   E]     b = [G^T v_free + (phi / h, 0, 0)]
///       [U            0],        [0                           ]
/// E = [0; I; I] adds lambda to the slip rows, U = [diag(mu), -I, -I] is the friction pyramid.
/// This is the planar form of Addi & Rodic (56)-(57) with one slack per contact instead of one
/// per direction; Anitescu & Potra (1997) show Lemke's method always solves it.
Lcp buildLcp(const Eigen::MatrixXd& g, const Eigen::MatrixXd& minv_g, const Eigen::VectorXd& v_free,
             double step, const std::vector<ContactRows>& contacts) {
  const Eigen::Index nc = static_cast<Eigen::Index>(contacts.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4 * nc, 4 * nc);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(4 * nc);
  a.topLeftCorner(3 * nc, 3 * nc) = g.transpose() * minv_g;
  b.head(3 * nc) = g.transpose() * v_free;
  for (Eigen::Index i = 0; i < nc; ++i) {
    const Eigen::Index lambda = 3 * nc + i;
    a(nc + i, lambda) = 1;
    a(2 * nc + i, lambda) = 1;
    a(lambda, i) = contacts[i].friction;
    a(lambda, nc + i) = -1;
    a(lambda, 2 * nc + i) = -1;
    b(i) += contacts[i].gap / step;
  }
  return {a, b};
}

}  // namespace

LcpStepResult lcpContactStep(const Eigen::MatrixXd& mass, const Eigen::VectorXd& force,
                             const Eigen::VectorXd& velocity, double step,
                             const std::vector<ContactRows>& contacts,
                             const LemkeOptions& options) {
  validate(mass, force, velocity, step, contacts);
  const Eigen::LLT<Eigen::MatrixXd> llt(mass);
  require(llt.info() == Eigen::Success, "mass matrix is not positive definite");
  const Eigen::Index nq = velocity.size();
  const Eigen::Index nc = static_cast<Eigen::Index>(contacts.size());
  const Eigen::MatrixXd g = impulseDirections(contacts, nq);
  const Eigen::MatrixXd minv_g = llt.solve(g);
  const Eigen::VectorXd v_free = velocity + step * llt.solve(force);
  const Lcp problem = buildLcp(g, minv_g, v_free, step, contacts);
  const LemkeResult lcp = solveLcp(problem.a, problem.b, options);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  LcpStepResult out{lcp.status, Eigen::VectorXd::Constant(nq, nan),
                    Eigen::VectorXd::Constant(nc, nan), Eigen::VectorXd::Constant(nc, nan),
                    lcp.pivots};
  if (lcp.status != LemkeStatus::kSolved) return out;
  const Eigen::VectorXd impulses = lcp.z.head(3 * nc);
  out.velocity = v_free + minv_g * impulses;  // impulse balance, Addi & Rodic (36)
  out.normal_impulse = impulses.head(nc);
  out.tangential_impulse = impulses.segment(nc, nc) - impulses.tail(nc);
  return out;
}

}  // namespace gaitopt::sim
