#pragma once
/// @file interior_contact.hpp
/// The single support's contact conditions (ground_contact.hpp: least normal force, friction
/// cone, ZMP) also between the collocation points. The stance force F_B = m (a_com + g e_y)
/// depends on the joint accelerations, which Hermite-Simpson reads between the points as the
/// quadratic through the segment's three (collocation_interpolation.hpp, what the export and a
/// controller receive); held at the points alone, the force is free to dip in between. A model
/// variant driven by a computed-torque law on a model off by Mu's case 2 met 150 N at every
/// point while its export pulled on the ground (-58 N) 4 ms after one, and the closed loop walked
/// on the rigid ground lifted its stance tip there (docs/optimal_gaits.md#between-the-points).
/// The rows are ground_contact's, at the interior ends of `sub_intervals` equal sub-intervals of
/// every segment (the midpoint, a point, skipped), on the export's own reading of the segment:
///   a(s) = sum_j b_j(s) a_j,  v(s) = v_0 + h sum_j c_j(s) a_j,
///   q(s) = q_0 + h s v_0 + h^2 sum_j d_j(s) a_j,  tau(s) = sum_j b_j(s) tau_j
/// (b, c, d: the Lagrange basis and its first and second integrals), linear in the segment's
/// variables for a fixed duration; so the rows' derivatives are ground_contact's through that
/// linear map.
#include <memory>
#include <string>
#include <vector>

#include "ocp/problem/ground_contact.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

class InteriorContact : public ConstraintSet {
 public:
  /// @throws std::invalid_argument for a double support, a scheme other than Hermite-Simpson, a
  /// free duration, or sub_intervals not even and >= 4.
  InteriorContact(std::string name, const Phase& phase,
                  std::shared_ptr<const GroundContact> contact, int sub_intervals);
  Eigen::VectorXd lowerBounds() const override;
  Eigen::VectorXd upperBounds() const override;
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;
  /// contact rows per sample, samples per segment.
  GridNode nodeOf(int row) const override {
    const int per_segment = static_cast<int>(samples_.size()) * contact_->rows();
    return {"segment", row / per_segment, row % per_segment};
  }

 private:
  /// The segment's variables the sample reads: q_0, v_0, a_0, a_1, a_2 (5 n, "motion"), then
  /// tau_0 at its three points.
  std::vector<int> localVariables(int k) const;
  /// The sample's point (point_layout.hpp) as a linear map of localVariables(k).
  Eigen::MatrixXd sampleMap(int k, double s) const;

  Phase phase_;
  std::shared_ptr<const GroundContact> contact_;
  std::vector<double> samples_;  // local times s in (0, 1)
};

}  // namespace gaitopt::ocp
