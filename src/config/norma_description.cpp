#include "spherical_robots/config/norma_description.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/config/urdf_model.hpp"

namespace spherical_robots::config {
namespace {

urdf::LinkConstSharedPtr requireLink(const urdf::ModelInterface& model, const std::string& name) {
  const urdf::LinkConstSharedPtr link = model.getLink(name);
  if (!link) throw std::invalid_argument("Norma URDF: no link '" + name + "'");
  return link;
}

urdf::JointConstSharedPtr requireJoint(const urdf::ModelInterface& model, const std::string& name,
                                       double ax, double ay, double az) {
  const urdf::JointConstSharedPtr joint = model.getJoint(name);
  if (!joint) throw std::invalid_argument("Norma URDF: no joint '" + name + "'");
  const urdf::Vector3& a = joint->axis;
  if (std::abs(a.x - ax) > 1e-9 || std::abs(a.y - ay) > 1e-9 || std::abs(a.z - az) > 1e-9) {
    throw std::invalid_argument("Norma URDF: joint '" + name + "' has axis (" +
                                std::to_string(a.x) + ", " + std::to_string(a.y) + ", " +
                                std::to_string(a.z) + "), expected (" + std::to_string(ax) +
                                ", " + std::to_string(ay) + ", " + std::to_string(az) + ")");
  }
  return joint;
}

urdf::InertialSharedPtr requireInertial(const urdf::ModelInterface& model,
                                        const std::string& name) {
  const urdf::LinkConstSharedPtr link = requireLink(model, name);
  if (!link->inertial) throw std::invalid_argument("Norma URDF: link '" + name + "' has no inertial");
  return link->inertial;
}

}  // namespace

norma::NormaParameters normaParametersFromUrdf(const std::string& urdf_xml) {
  const urdf::ModelInterfaceSharedPtr model = parseUrdf(urdf_xml, "Norma URDF");
  requireJoint(*model, "tilt_joint", 1, 0, 0);
  requireJoint(*model, "shell_joint", 0, 1, 0);
  const auto pendulum_joint = requireJoint(*model, "pendulum_joint", 0, -1, 0);
  const auto slider_joint = requireJoint(*model, "slider_joint", 0, 1, 0);
  norma::NormaParameters p;
  p.R = sphereRadiusFromUrdf(urdf_xml, "shell_link");
  p.m_shell = requireInertial(*model, "shell_link")->mass;
  p.m_shaft = requireInertial(*model, "shaft_link")->mass;
  const urdf::InertialSharedPtr pendulum = requireInertial(*model, "pendulum_link");
  p.m_pendulum = pendulum->mass;
  p.L = -pendulum->origin.position.z;
  p.L0 = -pendulum_joint->parent_to_joint_origin_transform.position.y;
  p.m_slider = requireInertial(*model, "slider_link")->mass;
  p.delta0 = slider_joint->parent_to_joint_origin_transform.position.y;
  norma::validate(p);  // names the first value that is not finite and > 0
  return p;
}

}  // namespace spherical_robots::config
