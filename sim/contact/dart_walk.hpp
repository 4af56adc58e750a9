#pragma once
/// @file dart_walk.hpp
/// Walking in the DART physics engine (DART 6.12, dartsim.github.io): the robot of
/// dynamics/robot_files/urdf_export.hpp, its feet bodies that tip when the centre of pressure
/// leaves them, on a floor box, advanced by DART's time stepping (semi-implicit Euler with its
/// boxed LCP contact solver and Coulomb friction from the robot file along the plane, restitution
/// 0; DART's own box-box collider). The root link is a PlanarJoint in the ZX plane, so the walk
/// stays in the x-z plane.
///
/// The toolkit closes the loop on DART's state once per time step (1 kHz with the shipped
/// configs/grounds/dart.yaml): the free-base state of free_base_walk.hpp is read from DART's
/// bodies (absolute link angles, the stance ankle as B), relabelled as the legs swap (Mu 2.38),
/// and the controller's joint torques go to the DART joints that are the model's joints in the
/// current labelling. The phases, relabelling, pushes and failure rule are free_base_walk.hpp's,
/// the same as on the toolkit's own grounds. The floor's top lies the sole depth below the tip
/// (FootBody), so a flat foot's tip is at the model's ground height y = 0.
///
/// The swing foot, which the model does not have, is held level by its ankle while it carries no
/// load: a velocity servo (DART's servo motor constraint, solved with the contacts) turns it back
/// to level within a few time steps; loaded, the ankle is a free hinge, as the model's leading
/// tip in double support (conventions.hpp).
///
/// Point feet (RABBIT) are balls on the tip whose ankles stay locked: the model's tip is a pivot,
/// and a ball on a free hinge is a wheel (the stance tip rolled 9.8 mm in 51 ms under 0.1 N of
/// floor traction). A locked ball rolls its centre by its radius per radian the shank turns,
/// hence the small radius of kExportFoot.
#include "sim/contact/ground_model.hpp"
#include "sim/walk/free_base_walk.hpp"

namespace gaitopt::sim {

/// The walk of free_base_walk.hpp in DART (impact = "dart"). DART and the libraries it pulls in
/// (FCL, Assimp, urdfdom, Octomap: 80 000 symbol relocations) live in a module of their own,
/// libgaitopt_dart.so beside libpardiso.so (dart_walk_module.cpp), loaded at the first DART walk:
/// linked into the tool, they took 15 ms of the dynamic linker's time at every start of every
/// command (gaitopt --version 21 ms against 8 ms without them), 12 % of a whole default solve.
/// @throws std::invalid_argument when this build has no DART (cmake -DGAITOPT_DART=ON),
/// std::runtime_error when the module cannot be loaded.
WalkResult walkDart(const dynamics::Model& plant, const Controller& controller,
                    const Reference& ref, const DartGround& ground, const WalkPlan& plan,
                    const WalkLog& log = {}, const VecD& theta0 = {}, const VecD& dtheta0 = {});

/// walkDart's signature, as the module hands it over.
using DartWalk = decltype(&walkDart);

/// The module's one exported symbol: a function returning its DartWalk.
inline constexpr const char* kDartModuleEntry = "gaitopt_dart_walk";
inline constexpr const char* kDartModuleName = "libgaitopt_dart.so";

}  // namespace gaitopt::sim
