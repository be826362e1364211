#include "spherical_robots/config/norma_description.hpp"

#include <cmath>
#include <stdexcept>
#include <urdf_parser/urdf_parser.h>

#include "spherical_robots/config/robot_description.hpp"

namespace spherical_robots::config {
namespace {

urdf::LinkConstSharedPtr requireLink(const urdf::ModelInterface& model, const std::string& name) {
  const urdf::LinkConstSharedPtr link = model.getLink(name);
  if (!link) throw std::invalid_argument("Norma URDF: no link '" + name + "'");
  return link;
}

double mass(const urdf::ModelInterface& model, const std::string& link_name) {
  const urdf::LinkConstSharedPtr link = requireLink(model, link_name);
  if (!link->inertial)
    throw std::invalid_argument("Norma URDF: link '" + link_name + "' has no <inertial>");
  return link->inertial->mass;
}

double length(const urdf::Vector3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

/// The distance [m] of joint `name` from its parent link's origin.
double jointDistance(const urdf::ModelInterface& model, const std::string& name) {
  const urdf::JointConstSharedPtr joint = model.getJoint(name);
  if (!joint) throw std::invalid_argument("Norma URDF: no joint '" + name + "'");
  return length(joint->parent_to_joint_origin_transform.position);
}

}  // namespace

norma::NormaParameters normaParametersFromUrdf(const std::string& urdf_xml) {
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model) throw std::invalid_argument("Norma URDF: the XML does not parse");
  norma::NormaParameters parameters;
  parameters.R = sphereRadiusFromUrdf(urdf_xml, "shell");
  parameters.m_shell = mass(*model, "shell");
  parameters.m_shaft = mass(*model, "shaft");
  parameters.m_pendulum = mass(*model, "pendulum");
  parameters.m_slider = mass(*model, "slider");
  const urdf::LinkConstSharedPtr pendulum = requireLink(*model, "pendulum");
  parameters.L = length(pendulum->inertial->origin.position);
  parameters.L0 = jointDistance(*model, "pendulum");
  parameters.delta0 = jointDistance(*model, "slider");
  norma::validate(parameters);  // names the parameter that is not finite and > 0
  return parameters;
}

}  // namespace spherical_robots::config
