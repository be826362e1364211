#pragma once
// Norma's masses and lengths from its URDF (urdf/norma.urdf, urdfdom), the one source of truth
// for the plant, the controller, sphere_sim and rviz.

#include <string>

#include "spherical_robots/norma/norma_dynamics.hpp"

namespace spherical_robots::config {

/// R: the radius of link `shell`'s collision sphere; m_shell, m_shaft, m_pendulum, m_slider: the
/// masses of links shell, shaft, pendulum, slider; L: the distance of the pendulum's inertial
/// origin (its bob) from joint `pendulum`; L0: that joint's distance from the centre; δ0: joint
/// `slider`'s distance from the centre. g stays 9.81 m/s².
/// @throw std::invalid_argument naming the link or joint that is missing or malformed, or the
///        parameter that is not finite and > 0.
norma::NormaParameters normaParametersFromUrdf(const std::string& urdf_xml);

}  // namespace spherical_robots::config
