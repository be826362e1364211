#pragma once
// Teleoperation: a planar velocity request (what a joystick or cmd_vel asks for) mapped onto what
// each robot type can actuate.

#include <string>
#include <vector>

#include "spherical_robots/terrain/robot_type.hpp"

namespace spherical_robots::terrain {

/// Requested motion in the heading frame (REP 103: x forward, y left, yaw about n).
struct VelocityRequest {
  double forward = 0.0;   ///< along h [m/s]
  double leftward = 0.0;  ///< along l [m/s]
  double yaw_rate = 0.0;  ///< about n [rad/s], counter-clockwise positive
};

struct TeleopCommand {
  DriveRates rates;
  /// Requested components the type can never follow ("leftward", "yaw_rate"); they are ignored.
  std::vector<std::string> ignored;
};

class TeleopMapping {
 public:
  /// @param radius R [m] > 0; @param tilt_limit RS |phi| limit [rad] in (0, pi/2);
  /// @param tilt_gain RS tilt servo gain [1/s] > 0. @throw std::invalid_argument naming the value.
  TeleopMapping(RobotType type, double radius, double tilt_limit, double tilt_gain);

  /// forward v -> roll rate v / R (eqs 33, 48); leftward v_y -> phi_dot = -v_y / R (3R, 2R: the
  /// centre moves with -R phi_dot l); yaw_rate -> psi_dot (3R, RT). RS steers by tilting: eq 44
  /// inverted gives the tilt phi* = asin(-yaw_rate / alpha_dot) (clamped to the limit; 0 when not
  /// rolling) and the tilt rate servos phi towards it, tilt_gain (phi* - phi), so releasing the
  /// stick levels the robot and it stops turning.
  /// @param tilt the RS tilt phi [rad] now (ignored by other types).
  /// @throw std::invalid_argument on a non-finite request or tilt.
  TeleopCommand command(const VelocityRequest& request, double tilt) const;

 private:
  RobotType type_;
  double radius_;
  double tilt_limit_;
  double tilt_gain_;
};

}  // namespace spherical_robots::terrain
