#pragma once
// Angles shared by the papers' models. No ROS.

namespace spherical_robots {

/// An angle [rad] wrapped into (−π, π].
double wrapToPi(double angle);

}  // namespace spherical_robots
