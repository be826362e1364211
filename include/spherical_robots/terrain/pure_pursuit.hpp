#pragma once
// Pure-pursuit tracking for the four robot types (paper eqs 53-58), in the sign convention of
// docs/conventions.md.

#include <Eigen/Core>

#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/terrain/robot_type.hpp"

namespace spherical_robots::terrain {

/// Gains; each type reads only its own. The member defaults are 3R's and RT's; defaultGains()
/// gives every type's (the values, also in config/terrain.yaml).
struct PursuitGains {
  double k_e = 0.5;  ///< error normalisation [m] (eqs 55-58)
  // 3R (eq 55) and RT (eq 57)
  double k_theta = 2.0;
  double k_phi1 = 2.0;
  double k_phi2 = 0.3;
  double k_psi = 1.0;
  // 2R (eq 56)
  double k_theta1 = 3.0;
  double k_theta2 = 0.3;
  // RS (eq 58)
  double k_alpha = 0.5;
  double k_phi = 2.0;
};

/// The default gains of a robot type (2R: k_theta1 3.0, k_theta2 0.3, k_phi1 3.0, k_phi2 0.3).
PursuitGains defaultGains(RobotType type);

/// Throws std::invalid_argument naming the first gain that is non-finite or negative, or k_e <= 0.
void validate(const PursuitGains& gains);

/// The paper's law (PursuitLaw::Paper).
class PurePursuitController final : public PursuitController {
 public:
  /// @throw std::invalid_argument on bad gains or radius.
  PurePursuitController(RobotType type, const PursuitGains& gains, double radius);

  /// Drive-rate set-points from the error and the desired point's 3D velocity
  /// (feed-forward |p_d'| / R, eqs 55, 57, 58).
  DriveRates command(const TrackingError& error, const Eigen::Vector3d& desired_velocity) const;

  /// The same: eqs 55-58 need neither the frame nor the tilt, and take p_d' at t itself.
  DriveRates command(const ContactGeometry& geometry, double tilt, const TrackingError& error,
                     const Eigen::Vector3d& desired_velocity) const override;
  VelocityWindow velocityWindow() const override { return {}; }
  bool readsZeta() const override { return true; }

  RobotType type() const override { return type_; }
  const PursuitGains& gains() const { return gains_; }

 private:
  RobotType type_;
  PursuitGains gains_;
  double radius_;
};

}  // namespace spherical_robots::terrain
