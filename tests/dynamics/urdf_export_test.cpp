// The exported URDF read back by DART's own URDF reader (dart::utils::DartLoader, DART 6.12):
// mass, CoM and the joint-space mass matrix of the stance-pinned chain against the model
// (Mu 2.8a, 2.44a) at random postures, the joint limits, and the feet as stated.
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/utils/urdf/DartLoader.hpp>

#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/robot_files/urdf_export.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using dart::dynamics::SkeletonPtr;

constexpr double kTol = 1e-9;
const std::vector<std::string> kRobots{"mu2004_five_link",  "rabbit",
                                       "three_link",        "compass_gait",
                                       "mu2004_three_link", "mu2004_compass_gait"};

/// The URDF with its stance foot welded to the world at the origin, flat: the stance-pinned
/// chain of Mu (2.7), whose generalized coordinates are the model's q (urdf_export.hpp).
SkeletonPtr loadPinned(const dynamics::Model& model) {
  using Loader = dart::utils::DartLoader;
  Loader loader(Loader::Options(nullptr, Loader::RootJointType::FIXED));
  SkeletonPtr skel =
      loader.parseSkeletonString(dynamics::urdfText(model, dynamics::kExportFoot), "");
  if (!skel) throw std::runtime_error("DART could not read the URDF of " + model.name());
  return skel;
}

/// DART's index of the model's joint j.
std::size_t dofIndex(const SkeletonPtr& skel, const dynamics::Model& model, int j) {
  return skel->getJoint(model.joints()[static_cast<size_t>(j)].name)->getIndexInSkeleton(0);
}

void removeFeet(const SkeletonPtr& skel) {
  for (const char* foot : {dynamics::kStanceFootLink, dynamics::kSwingFootLink}) {
    auto* body = skel->getBodyNode(foot);
    body->setMass(0);
    body->setMomentOfInertia(0, 0, 0);
  }
}

/// Sets DART's coordinates to q (joint order of the model) and a random swing ankle.
void setPosture(const SkeletonPtr& skel, const dynamics::Model& model, const VecD& q,
                double swing_ankle) {
  for (int j = 0; j < model.nLinks(); ++j) skel->setPosition(dofIndex(skel, model, j), q(j));
  skel->getJoint(dynamics::kSwingAnkleJoint)->setPosition(0, swing_ankle);
}

class UrdfExport : public ::testing::TestWithParam<std::string> {};

TEST_P(UrdfExport, MassComAndJointSpaceMassMatrixMatchTheModel) {
  const auto model = loadNamed(GetParam());
  const SkeletonPtr skel = loadPinned(model);
  const int n = model.nLinks();
  ASSERT_EQ(skel->getNumDofs(), static_cast<size_t>(n + 1));  // the model's joints, swing ankle
  EXPECT_NEAR(skel->getMass(), model.totalMass() + 2 * dynamics::kExportFoot.mass, kTol);
  removeFeet(skel);
  EXPECT_NEAR(skel->getMass(), model.totalMass(), kTol);
  std::mt19937 rng(35);
  for (int k = 0; k < 20; ++k) {
    const VecD theta = randomPosture(rng, model);
    const VecD q = dynamics::toJoint(theta);
    setPosture(skel, model, q, randomVec(rng, 1, -1, 1)(0));
    const Eigen::Vector3d com = skel->getCOM();
    const Vec2d expected_com = dynamics::centreOfMass(model, theta);
    EXPECT_NEAR(com.x(), expected_com(0), kTol) << "posture " << k;
    EXPECT_NEAR(com.y(), 0, kTol) << "posture " << k;
    EXPECT_NEAR(com.z(), expected_com(1), kTol) << "posture " << k;
    const MatD expected = dynamics::jointSpaceMassMatrix(dynamics::massMatrix(model, theta));
    const Eigen::MatrixXd& m = skel->getMassMatrix();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        EXPECT_NEAR(m(dofIndex(skel, model, i), dofIndex(skel, model, j)), expected(i, j), kTol)
            << "posture " << k << ", M(" << i << ", " << j << ")";
  }
}

/// Continuous joints about y: no position limits, effort = torque_limit (0 unactuated),
/// velocity = velocity_limit; the swing ankle takes joint 0's.
void expectLimits(const dart::dynamics::Joint* joint, const dynamics::Joint& expected) {
  const auto* revolute = dynamic_cast<const dart::dynamics::RevoluteJoint*>(joint);
  ASSERT_NE(revolute, nullptr) << joint->getName();
  EXPECT_DOUBLE_EQ(std::abs(revolute->getAxis().y()), 1.0) << joint->getName();
  EXPECT_EQ(joint->getForceUpperLimit(0), expected.torque_limit) << joint->getName();
  EXPECT_EQ(joint->getForceLowerLimit(0), -expected.torque_limit) << joint->getName();
  EXPECT_EQ(joint->getVelocityUpperLimit(0), expected.velocity_limit) << joint->getName();
  EXPECT_EQ(joint->getVelocityLowerLimit(0), -expected.velocity_limit) << joint->getName();
  EXPECT_EQ(joint->getPositionUpperLimit(0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(joint->getPositionLowerLimit(0), -std::numeric_limits<double>::infinity());
}

TEST_P(UrdfExport, JointLimitsAreTheModels) {
  const auto model = loadNamed(GetParam());
  const SkeletonPtr skel = loadPinned(model);
  for (const auto& joint : model.joints()) expectLimits(skel->getJoint(joint.name), joint);
  expectLimits(skel->getJoint(dynamics::kSwingAnkleJoint), model.joints()[0]);
}

/// Feet as stated: a box from heel to toe with its sole below the tip, or a sphere on the tip.
TEST_P(UrdfExport, FeetAreTheRobotFilesHeelAndToe) {
  const auto model = loadNamed(GetParam());
  const SkeletonPtr skel = loadPinned(model);
  const auto& f = dynamics::kExportFoot;
  for (const char* name : {dynamics::kStanceFootLink, dynamics::kSwingFootLink}) {
    const auto* foot = skel->getBodyNode(name);
    EXPECT_EQ(foot->getMass(), f.mass);
    const auto shapes = foot->getShapeNodesWith<dart::dynamics::CollisionAspect>();
    ASSERT_EQ(shapes.size(), 1u) << name;
    const auto shape = shapes[0]->getShape();
    const double length = model.foot().heel + model.foot().toe;
    if (length > 0) {
      const auto* box = dynamic_cast<const dart::dynamics::BoxShape*>(shape.get());
      ASSERT_NE(box, nullptr) << name;
      EXPECT_EQ(box->getSize(), Eigen::Vector3d(length, f.width, f.thickness));
      const Eigen::Vector3d centre = shapes[0]->getRelativeTranslation();
      EXPECT_NEAR(centre.x(), (model.foot().toe - model.foot().heel) / 2, kTol);
      EXPECT_NEAR(centre.z(), -f.thickness / 2, kTol);
    } else {
      const auto* sphere = dynamic_cast<const dart::dynamics::SphereShape*>(shape.get());
      ASSERT_NE(sphere, nullptr) << name;
      EXPECT_EQ(sphere->getRadius(), f.radius);
    }
  }
}

/// Flat on the ground the swing foot's sole is level with the stance foot's: both feet face
/// the ground the same way, toe forward, so relabelling (Mu 2.38) swaps them whole.
TEST_P(UrdfExport, SwingFootMirrorsTheStanceFoot) {
  const auto model = loadNamed(GetParam());
  const SkeletonPtr skel = loadPinned(model);
  std::mt19937 rng(38);
  const VecD theta = randomPosture(rng, model);
  // Swing ankle angle that levels the swing foot: the shank from the foot, as for the stance.
  const double swing_ankle = theta(model.nLinks() - 1) - std::numbers::pi;
  setPosture(skel, model, dynamics::toJoint(theta), swing_ankle);
  const Eigen::Isometry3d foot = skel->getBodyNode(dynamics::kSwingFootLink)->getWorldTransform();
  EXPECT_LT((foot.linear() - Eigen::Matrix3d::Identity()).norm(), kTol);
  const Vec2d tip = dynamics::swingTip(model, theta);
  EXPECT_NEAR(foot.translation().x(), tip(0), kTol);
  EXPECT_NEAR(foot.translation().z(), tip(1), kTol);
}

INSTANTIATE_TEST_SUITE_P(ShippedRobots, UrdfExport, ::testing::ValuesIn(kRobots));

}  // namespace
}  // namespace gaitopt::test
