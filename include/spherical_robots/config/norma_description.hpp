#pragma once
// Norma's masses and lengths read from its URDF (urdf/norma.urdf), the one source of truth for
// rviz and the model (urdfdom).

#include <string>

#include "spherical_robots/norma/norma_dynamics.hpp"

namespace spherical_robots::config {

/// R from shell_link's sphere; m_shell, m_shaft, m_pendulum, m_slider from the inertial masses of
/// shell_link, shaft_link, pendulum_link, slider_link; L0 = −y of pendulum_joint's origin; L = −z
/// of pendulum_link's inertial origin; delta0 = y of slider_joint's origin. g keeps its default.
/// The joints must have the axes of docs/conventions.md ("Norma"): tilt_joint +x, shell_joint
/// +y, pendulum_joint −y, slider_joint +y.
/// @throw std::invalid_argument if the XML does not parse, a link, joint or inertial is missing,
///        an axis differs, or a value is not finite and > 0 (naming it).
norma::NormaParameters normaParametersFromUrdf(const std::string& urdf_xml);

}  // namespace spherical_robots::config
