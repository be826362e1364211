#pragma once
// Angles shared by the papers' models. No ROS.

#include <Eigen/Geometry>

namespace spherical_robots {

/// An angle [rad] wrapped into (−π, π].
double wrapToPi(double angle);

/// The turn by `yaw` [rad] about z: the attitude of a gravity-aligned body (base_link) heading
/// that way.
Eigen::Quaterniond yawRotation(double yaw);

/// The yaw [rad] of an attitude's x axis projected on the horizontal plane (REP 103: z up): the
/// heading of a gravity-aligned base_link, and the same for a source whose base_link also rolls
/// and pitches. The quaternion need not be normalised (the formula is homogeneous in it).
/// @throw std::invalid_argument if a coefficient is not finite or the x axis is vertical.
double yawOf(const Eigen::Quaterniond& orientation);

}  // namespace spherical_robots
