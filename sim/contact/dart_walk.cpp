#include "sim/contact/dart_walk.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <dart/collision/CollisionObject.hpp>
#include <dart/collision/CollisionResult.hpp>
#include <dart/collision/dart/DARTCollisionDetector.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/PlanarJoint.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>
#include <dart/utils/urdf/DartLoader.hpp>

#include "dynamics/impact/relabel.hpp"
#include "dynamics/robot_files/urdf_export.hpp"

namespace gaitopt::sim {
namespace {

using dart::dynamics::BodyNode;
using dart::dynamics::DegreeOfFreedom;

/// A body's absolute angle theta (conventions.hpp): its z axis is (sin theta, 0, cos theta).
double angleOf(const BodyNode* body) {
  const Eigen::Vector3d z = body->getWorldTransform().linear().col(2);
  return std::atan2(z.x(), z.z());
}

/// theta-dot of a body turning in the x-z plane: its angular velocity about +y [rad/s].
double rateOf(const BodyNode* body) {
  return body->getAngularVelocity().y();
}

/// A point foot (heel = toe = 0) is exported as a sphere on the tip (urdf_export.hpp).
bool pointFeet(const dynamics::Model& plant) {
  return plant.foot().heel + plant.foot().toe <= 0;
}

/// How deep the sole lies below the tip (urdf_export.hpp) [m].
double soleDepth(const dynamics::Model& plant, const dynamics::FootBody& foot) {
  return pointFeet(plant) ? foot.radius : foot.thickness;
}

/// Coulomb friction mu along the walking plane (x) and none across it. The skeleton is planar, so
/// nothing moves across the plane: with DART's default second friction direction the contact LCP
/// has rows of zero mobility, its Dantzig solver returned NaN at every time step (535 of the 536
/// of a walk) and DART fell back on 30 projected Gauss-Seidel sweeps, whose residual let the stance
/// foot roll heel-down by 0.02 rad (4 mm) within one single support.
void planarFriction(dart::dynamics::DynamicsAspect* aspect, double mu) {
  aspect->setFrictionCoeff(mu);
  aspect->setFirstFrictionDirection(Eigen::Vector3d::UnitX());
  aspect->setFirstFrictionDirectionFrame(dart::dynamics::Frame::World());
  aspect->setSecondaryFrictionCoeff(0.0);
}

/// The robot and its floor in one DART world, and which foot is the stance foot.
class DartPlant {
 public:
  DartPlant(const dynamics::Model& plant, const DartGround& ground)
      : plant_(plant), world_(dart::simulation::World::create()) {
    world_->setTimeStep(ground.time_step);
    const Vec2d g = plant.gravityAcceleration();  // in the ground frame (model.hpp)
    world_->setGravity(Eigen::Vector3d(g.x(), 0, g.y()));
    loadRobot();
    addFloor();
    // DART's own box-box collider touches a flat foot at its four corners. FCL, DART's default,
    // meshes the boxes: it touched the stance foot at 8 or 9 points and let its tip slide
    // 0.12 mm in the first millisecond, where DART's collider holds it to 0.01 mm.
    world_->getConstraintSolver()->setCollisionDetector(
        dart::collision::DARTCollisionDetector::create());
  }

  ContactStep step(const FreeBaseState& s, const TorqueFeedback& torque) {
    if (!started_) start(s);
    followRelabelling(s);
    actuateAnkles();
    robot_->setForces(jointForces(torque(0.0, s.q, s.v)));
    if (swingServo()) holdSwingFootLevel();
    if (!s.hip_force.isZero())
      links_[static_cast<size_t>(plant_.legLinks())]->addExtForce(
          Eigen::Vector3d(s.hip_force.x(), 0, s.hip_force.y()), Eigen::Vector3d::Zero(), false,
          true);
    world_->step();
    forces_ = contactForces();
    // A point foot's ball turns with its locked ankle: it has no flat to tilt from.
    const double tilt = pointFeet(plant_) ? 0.0 : angleOf(feet_[static_cast<size_t>(side_)]);
    ContactStep out{observe(), {}, "", tilt};
    out.next.hip_force = s.hip_force;
    out.force = {forces_[static_cast<size_t>(side_)], forces_[static_cast<size_t>(1 - side_)]};
    return out;
  }

 private:
  void loadRobot() {
    dart::utils::DartLoader loader;
    robot_ = loader.parseSkeletonString(dynamics::urdfText(plant_, dynamics::kExportFoot), "");
    if (!robot_) throw std::runtime_error("DART could not read the robot's URDF");
    auto* root = robot_->getRootBodyNode()->changeParentJointType<dart::dynamics::PlanarJoint>();
    root->setZXPlane();  // positions (z, x, turn about z x x = +y)
    root_ = root;
    for (const auto& link : plant_.links()) links_.push_back(robot_->getBodyNode(link.name));
    feet_ = {robot_->getBodyNode(dynamics::kStanceFootLink),
             robot_->getBodyNode(dynamics::kSwingFootLink)};
    ankles_ = {robot_->getJoint(plant_.joints()[0].name)->getDof(0),
               robot_->getJoint(dynamics::kSwingAnkleJoint)->getDof(0)};
    for (size_t j = 1; j < plant_.joints().size(); ++j)
      joints_.push_back(robot_->getJoint(plant_.joints()[j].name)->getDof(0));
    for (auto* foot : feet_)
      for (auto* shape : foot->getShapeNodesWith<dart::dynamics::DynamicsAspect>())
        planarFriction(shape->getDynamicsAspect(), plant_.friction());
    world_->addSkeleton(robot_);
  }

  /// A 200 m long box whose top face is the floor, the sole depth below the model's y = 0.
  void addFloor() {
    auto floor = dart::dynamics::Skeleton::create("floor");
    auto* body = floor->createJointAndBodyNodePair<dart::dynamics::WeldJoint>().second;
    auto shape = std::make_shared<dart::dynamics::BoxShape>(Eigen::Vector3d(200, 1, 1));
    auto* node =
        body->createShapeNodeWith<dart::dynamics::CollisionAspect, dart::dynamics::DynamicsAspect>(
            shape);
    node->setRelativeTranslation(
        Eigen::Vector3d(0, 0, -soleDepth(plant_, dynamics::kExportFoot) - 0.5));
    planarFriction(node->getDynamicsAspect(), plant_.friction());
    world_->addSkeleton(floor);
  }

  /// DART's state from the free-base start s (stance foot flat at B, swing foot level).
  void start(const FreeBaseState& s) {
    const int n = plant_.nLinks();
    const VecD theta = s.q.tail(n), dtheta = s.v.tail(n);
    // A locked ankle (point feet) turns the ball with the shank: the root carries its angle.
    const bool point = pointFeet(plant_);
    root_->setPositions(Eigen::Vector3d(s.q(1), s.q(0), point ? theta(0) : 0.0));
    root_->setVelocities(Eigen::Vector3d(s.v(1), s.v(0), point ? dtheta(0) : 0.0));
    if (!point) {
      ankles_[0]->setPosition(theta(0));
      ankles_[0]->setVelocity(dtheta(0));
    }
    for (int j = 1; j < n; ++j) {
      joints_[static_cast<size_t>(j - 1)]->setPosition(theta(j - 1) - theta(j));
      joints_[static_cast<size_t>(j - 1)]->setVelocity(dtheta(j - 1) - dtheta(j));
    }
    ankles_[1]->setPosition(theta(n - 1) + std::numbers::pi);  // the swing foot level
    ankles_[1]->setVelocity(point ? 0.0 : dtheta(n - 1));
    started_ = true;
  }

  /// The tip of foot k (its frame's origin) in the x-z plane [m].
  Vec2d tip(int k) const {
    const Eigen::Vector3d p = feet_[static_cast<size_t>(k)]->getWorldTransform().translation();
    return {p.x(), p.z()};
  }

  /// The walk relabels its state at a step's end (Mu 2.38): B is then the other foot's tip.
  void followRelabelling(const FreeBaseState& s) {
    const Vec2d b = s.q.head<2>();
    if ((b - tip(1 - side_)).norm() < (b - tip(side_)).norm()) side_ = 1 - side_;
  }

  /// The free-base state (x_b, y_b, theta) in the current labelling: URDF order on side 0, the
  /// chain reversed and the legs turned by pi on side 1 (relabelAngles), angles wrapped as there.
  FreeBaseState observe() const {
    const int n = plant_.nLinks();
    VecD theta(n), dtheta(n);
    for (int i = 0; i < n; ++i) {
      theta(i) = angleOf(links_[static_cast<size_t>(i)]);
      dtheta(i) = rateOf(links_[static_cast<size_t>(i)]);
    }
    // relabelAngles of the relabelled angles wraps them on side 0's ranges.
    theta = dynamics::relabelAngles<double>(plant_, theta);
    if (side_ == 0) {
      theta = dynamics::relabelAngles<double>(plant_, theta);
    } else {
      dtheta = dynamics::relabelRates<double>(dtheta);
    }
    const auto* stance = feet_[static_cast<size_t>(side_)];
    const Eigen::Vector3d v = stance->getLinearVelocity();
    FreeBaseState s{Eigen::VectorXd(n + 2), Eigen::VectorXd(n + 2)};
    s.q << tip(side_), theta;
    s.v << v.x(), v.z(), dtheta;
    return s;
  }

  /// The model's joint torques on DART's joints in the current labelling (the swing ankle's is
  /// zero: it is a free hinge or a servo). Side 1: the model's joint j >= 1 is URDF joint n - j
  /// turned round, q'_j = -q_{n-j} + const (relabelAngles), so it takes -tau_j.
  Eigen::VectorXd jointForces(const VecD& tau) {
    const int n = plant_.nLinks();
    Eigen::VectorXd f = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(robot_->getNumDofs()));
    const auto add = [&f](DegreeOfFreedom* dof, double value) {
      f(static_cast<Eigen::Index>(dof->getIndexInSkeleton())) += value;
    };
    add(ankles_[static_cast<size_t>(side_)], tau(0));
    for (int j = 1; j < n; ++j)
      add(joints_[static_cast<size_t>(side_ == 0 ? j - 1 : n - j - 1)],
          side_ == 0 ? tau(j) : -tau(j));
    return f;
  }

  /// The swing ankle is a servo while its foot carries no load and it is actuated; a point
  /// foot's ankles are locked (actuateAnkles), and a servo command to one warns every time step.
  bool swingServo() const {
    return plant_.joints()[0].actuated && !pointFeet(plant_) &&
           forces_[static_cast<size_t>(1 - side_)].y() <= 0;
  }

  /// The stance ankle takes the controller's torque; the swing ankle is a velocity servo or, on a
  /// loaded foot, a free hinge as the model's leading tip in double support (conventions.hpp).
  /// Set before the forces: DART applies a force joint's command, which setForces writes.
  void actuateAnkles() {
    if (pointFeet(plant_)) {
      for (auto* ankle : ankles_) ankle->getJoint()->setActuatorType(dart::dynamics::Joint::LOCKED);
      return;
    }
    ankles_[static_cast<size_t>(side_)]->getJoint()->setActuatorType(dart::dynamics::Joint::FORCE);
    ankles_[static_cast<size_t>(1 - side_)]->getJoint()->setActuatorType(
        swingServo() ? dart::dynamics::Joint::SERVO : dart::dynamics::Joint::FORCE);
  }

  /// Turns the unloaded foot back to level with time constant kServoSteps time steps: DART's
  /// servo constraint reaches the commanded ankle rate within the step, solved with the
  /// contacts (within the ankle's torque limit), where a PD torque is explicit and could hold
  /// only a bandwidth of 0.1 / h: it left the swing foot 0.026 rad toe-down late in the swing,
  /// its toe 5 mm below its heel, and the foot landed on its toe. The ankle's positive turn lowers
  /// the foot's angle (both ankles measure the shank from the foot), so the foot turns at the
  /// shank's rate minus the ankle's.
  void holdSwingFootLevel() {
    constexpr double kServoSteps = 4;
    const int swing = 1 - side_;
    const BodyNode* foot = feet_[static_cast<size_t>(swing)];
    const BodyNode* shank = swing == 0 ? links_.front() : links_.back();
    const double tau = kServoSteps * world_->getTimeStep();
    ankles_[static_cast<size_t>(swing)]->setCommand(rateOf(shank) + angleOf(foot) / tau);
  }

  /// The floor's force on each foot over the last time step, (x, z) [N].
  std::array<Vec2d, 2> contactForces() const {
    std::array<Vec2d, 2> out{Vec2d::Zero(), Vec2d::Zero()};
    for (const auto& c : world_->getLastCollisionResult().getContacts()) {
      const auto* body1 =
          c.collisionObject1->getShapeFrame()->asShapeNode()->getBodyNodePtr().get();
      const auto* body2 =
          c.collisionObject2->getShapeFrame()->asShapeNode()->getBodyNodePtr().get();
      for (int k = 0; k < 2; ++k) {
        const auto* foot = feet_[static_cast<size_t>(k)];
        // Contact::force acts on body 1 (DART's Contact.hpp), -force on body 2. Only the floor's:
        // a foot that touches the other foot or a shank (legs passing at mid-swing) carries a
        // force of the robot on itself, which is no ground reaction (it read 8 kN, 9 times mu).
        const auto* other = body1 == foot ? body2 : body2 == foot ? body1 : nullptr;
        if (other == nullptr || other->getSkeleton() == robot_) continue;
        const double sign = body1 == foot ? 1.0 : -1.0;
        out[static_cast<size_t>(k)] += sign * Vec2d(c.force.x(), c.force.z());
      }
    }
    return out;
  }

  const dynamics::Model& plant_;
  dart::simulation::WorldPtr world_;
  dart::dynamics::SkeletonPtr robot_;
  dart::dynamics::PlanarJoint* root_ = nullptr;
  std::vector<BodyNode*> links_;              ///< URDF (side 0) order
  std::array<BodyNode*, 2> feet_{};           ///< stance_foot, swing_foot of the URDF
  std::array<DegreeOfFreedom*, 2> ankles_{};  ///< the stance ankle and swing_ankle of the URDF
  std::vector<DegreeOfFreedom*> joints_;      ///< URDF joints 1..n-1
  std::array<Vec2d, 2> forces_{Vec2d::Zero(), Vec2d::Zero()};  ///< on each foot, last step
  int side_ = 0;  ///< which URDF foot is the stance foot B
  bool started_ = false;
};

WalkResult walkInDart(const dynamics::Model& plant, const Controller& controller,
                      const Reference& ref, const DartGround& ground, const WalkPlan& plan,
                      const WalkLog& log, const VecD& theta0, const VecD& dtheta0) {
  auto dart = std::make_shared<DartPlant>(plant, ground);
  const FreeBaseGround free_base{"dart", ground.time_step,
                                 [dart](const FreeBaseState& s, const TorqueFeedback& torque) {
                                   return dart->step(s, torque);
                                 }};
  return walkFreeBase(plant, controller, ref, free_base, plan, log, theta0, dtheta0);
}

}  // namespace

}  // namespace gaitopt::sim

/// What dart_walk_module.cpp looks up in this module (kDartModuleEntry).
extern "C" __attribute__((visibility("default"))) gaitopt::sim::DartWalk gaitopt_dart_walk() {
  return &gaitopt::sim::walkInDart;
}
