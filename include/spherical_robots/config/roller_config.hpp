#pragma once
// The roller stack's friction drive (launch/roller_stack.launch), from parameters under roller/
// (config/roller.yaml): where the two rollers touch the sphere, their arrangement angles and
// radius. The sphere's radius is not here: it is base_link's sphere in the URDF.

#include <array>
#include <string>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/roller/roller_actuation.hpp"
#include "spherical_robots/roller/roller_geometry.hpp"

namespace spherical_robots::config {

/// The actuator names of the roller stack on actuators/command and actuators/state: the motors of
/// the paper's roller 1 and roller 2, angular rates [rad/s].
inline const std::array<std::string, 2>& kRollerActuatorNames = roller::kMotorNames;

/// Defaults: the paper's drive (section 3: P1 at azimuth 215°, P2 at 325°, both at 60° elevation;
/// α1 = −α2 = 30°) with 30 mm rollers.
struct RollerConfig {
  double roller_radius = 0.03;  ///< [m]
  roller::SphericalDirection contact1{215.0, 60.0};  ///< azimuth, elevation of P1 [deg]
  roller::SphericalDirection contact2{325.0, 60.0};  ///< of P2 [deg]
  double alpha1 = 30.0;  ///< α1 [deg]
  double alpha2 = -30.0;  ///< α2 [deg]
};

/// Keys roller/roller_radius, roller/contact1/{azimuth_deg,elevation_deg}, roller/contact2/...,
/// roller/alpha1_deg, roller/alpha2_deg; each optional (RollerConfig's default).
/// @throw std::invalid_argument naming the key on a value that is not a finite number.
RollerConfig loadRollerConfig(const ParameterSource& source);

/// The drive for a sphere of radius [m]. @throw std::invalid_argument naming the problem (a
/// degenerate geometry, a radius <= 0).
roller::RollerActuation makeRollerActuation(const RollerConfig& config, double sphere_radius);

}  // namespace spherical_robots::config
