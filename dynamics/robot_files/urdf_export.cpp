#include "dynamics/robot_files/urdf_export.hpp"

#include <numbers>
#include <set>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include <fmt/format.h>

namespace gaitopt::dynamics {
namespace {

/// A name as XML attribute text (XML 1.0 sec. 2.4: &, <, > and quotes escaped).
std::string attribute(std::string_view name) {
  std::string out;
  for (const char c : name) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// URDF requires unique link and joint names (separately); XML 1.0 has no control characters.
void requireNames(const std::vector<std::string>& names, std::string_view kind) {
  std::set<std::string> seen;
  for (const auto& name : names) {
    if (name.empty()) throw std::invalid_argument(fmt::format("a {} name is empty", kind));
    for (const char c : name)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
        throw std::invalid_argument(
            fmt::format("a {} name holds the control character {:#04x}", kind, int(c)));
    if (!seen.insert(name).second)
      throw std::invalid_argument(
          fmt::format("{} name '{}' is used twice (the URDF adds {}, {} and {})", kind, name,
                      kStanceFootLink, kSwingFootLink, kSwingAnkleJoint));
  }
}

void checkNames(const Model& model) {
  std::vector<std::string> links{kStanceFootLink, kSwingFootLink};
  for (const auto& l : model.links()) links.push_back(l.name);
  std::vector<std::string> joints{kSwingAnkleJoint};
  for (const auto& j : model.joints()) joints.push_back(j.name);
  requireNames(links, "link");
  requireNames(joints, "joint");
}

/// <inertial> with the CoM at (x, 0, z) of the link frame and a diagonal inertia tensor.
std::string inertial(double mass, double x, double z, const Eigen::Vector3d& moments) {
  return fmt::format(
      "    <inertial>\n      <origin xyz=\"{} 0 {}\" rpy=\"0 0 0\"/>\n      <mass value=\"{}\"/>\n"
      "      <inertia ixx=\"{}\" ixy=\"0\" ixz=\"0\" iyy=\"{}\" iyz=\"0\" izz=\"{}\"/>\n"
      "    </inertial>\n",
      x, z, mass, moments.x(), moments.y(), moments.z());
}

/// A chain link: only I_i about y enters planar motion; ixx = izz = iyy keeps the tensor
/// physical (the triangle inequality of principal moments) for 3-D tools.
std::string linkXml(const Link& link) {
  return fmt::format("  <link name=\"{}\">\n{}  </link>\n", attribute(link.name),
                     inertial(link.mass, 0, link.com, Eigen::Vector3d::Constant(link.inertia)));
}

/// Geometry and inertia of a foot in its own frame (origin at the tip, z up when flat).
std::string footXml(const char* name, const Foot& foot, const FootBody& body) {
  const double length = foot.heel + foot.toe;
  std::string geometry;
  double x = 0, z = 0;
  Eigen::Vector3d moments;
  if (length > 0) {
    const double h = body.thickness, w = body.width, m = body.mass;
    x = (foot.toe - foot.heel) / 2;
    z = -h / 2;
    // Solid box about its centre: I = m (a^2 + b^2) / 12 for the two other edges.
    moments = {m * (w * w + h * h) / 12, m * (length * length + h * h) / 12,
               m * (length * length + w * w) / 12};
    geometry = fmt::format("<box size=\"{} {} {}\"/>", length, w, h);
  } else {
    moments.setConstant(0.4 * body.mass * body.radius * body.radius);  // solid sphere, 2/5 m r^2
    geometry = fmt::format("<sphere radius=\"{}\"/>", body.radius);
  }
  const std::string shape =
      fmt::format("      <origin xyz=\"{} 0 {}\" rpy=\"0 0 0\"/>\n      <geometry>{}</geometry>\n",
                  x, z, geometry);
  return fmt::format(
      "  <link name=\"{}\">\n{}    <visual>\n{}    </visual>\n    <collision>\n{}    "
      "</collision>\n  </link>\n",
      name, inertial(body.mass, x, z, moments), shape, shape);
}

struct JointPlacement {
  std::string parent, child;
  double z = 0;       ///< offset along the parent's z [m]
  double pitch = 0;   ///< turn about y of the joint frame [rad]
  double axis_y = 0;  ///< +1 or -1
};

std::string jointXml(const Joint& joint, const std::string& name, const JointPlacement& p) {
  return fmt::format(
      "  <joint name=\"{}\" type=\"continuous\">\n    <parent link=\"{}\"/>\n"
      "    <child link=\"{}\"/>\n    <origin xyz=\"0 0 {}\" rpy=\"0 {} 0\"/>\n"
      "    <axis xyz=\"0 {} 0\"/>\n    <limit effort=\"{}\" velocity=\"{}\"/>\n  </joint>\n",
      attribute(name), attribute(p.parent), attribute(p.child), p.z, p.pitch, p.axis_y,
      joint.torque_limit, joint.velocity_limit);
}

}  // namespace

std::string urdfText(const Model& model, const FootBody& foot) {
  checkNames(model);
  const int n = model.nLinks();
  std::string out = fmt::format(
      "<?xml version=\"1.0\"?>\n<!-- gaitopt export-urdf: planar in x-z (z up), joints about y; "
      "the root link {} has no parent joint: make it planar (or weld it) when loading. -->\n"
      "<robot name=\"{}\">\n",
      kStanceFootLink, attribute(model.name()));
  out += footXml(kStanceFootLink, model.foot(), foot);
  out += jointXml(model.joints()[0], model.joints()[0].name,
                  {kStanceFootLink, model.link(0).name, 0, 0, 1});
  for (int j = 0; j < n; ++j) {
    out += linkXml(model.link(j));
    if (j + 1 < n) {
      const Link& parent = model.link(j);
      out += jointXml(model.joints()[static_cast<size_t>(j + 1)],
                      model.joints()[static_cast<size_t>(j + 1)].name,
                      {parent.name, model.link(j + 1).name, parent.a() * parent.length, 0, -1});
    }
  }
  const Link& last = model.link(n - 1);
  out += jointXml(model.joints()[0], kSwingAnkleJoint,
                  {last.name, kSwingFootLink, last.length, std::numbers::pi, -1});
  out += footXml(kSwingFootLink, model.foot(), foot);
  return out + "</robot>\n";
}

}  // namespace gaitopt::dynamics
