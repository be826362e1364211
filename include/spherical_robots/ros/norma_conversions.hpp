#pragma once
// The Norma stack's messages: NormaState both ways, the URDF's joints, the actuators' efforts,
// the tracking error and the path of eq 52 for rviz.

#include <nav_msgs/Path.h>
#include <sensor_msgs/JointState.h>

#include <string>
#include <vector>

#include "spherical_robots/NormaState.h"
#include "spherical_robots/TrackingError.h"
#include "spherical_robots/norma/norma_control_loop.hpp"
#include "spherical_robots/norma/norma_controller.hpp"
#include "spherical_robots/norma/norma_plant.hpp"
#include "spherical_robots/ros/conversions.hpp"

namespace spherical_robots::conversions {

/// The actuators of the pendulum torque T and the slider force F, in this order.
const std::vector<std::string>& normaActuatorNames();

/// The plant's state, with the efforts that drove it and its total energy [J].
spherical_robots::NormaState toNormaStateMsg(const norma::NormaState& state,
                                             const norma::Efforts& driving, double energy,
                                             const ros::Time& stamp);

/// The measurement a NormaState message carries (the control loop validates it).
norma::NormaMeasurement normaMeasurementFromMsg(const spherical_robots::NormaState& msg);

/// The URDF's joints (urdf/norma.urdf): tilt φ, shell θ, pendulum α (relative to the shell),
/// slider δ, with positions and rates.
sensor_msgs::JointState normaJointState(const norma::NormaState& state, const ros::Time& stamp);

/// The actuators' command: T [N m] and F [N] as efforts.
sensor_msgs::JointState normaEffortCommand(double torque, double force, const ros::Time& stamp);

/// The error to the reference point of the path, in the plane z = 0 of `frame` (the odometry's).
/// @param error_norm, zeta what the controller computed for this state (|e| [m], ζ [rad]).
spherical_robots::TrackingError toNormaTrackingErrorMsg(const norma::PathPoint& reference, double x,
                                                        double y, double error_norm, double zeta,
                                                        const std::string& frame,
                                                        const ros::Time& stamp);

/// One period [s] of the path of eq 52 in `frame`, `samples` + 1 poses (closing the loop).
nav_msgs::Path lissajousPathMsg(double period, int samples, const std::string& frame,
                                const ros::Time& stamp);

}  // namespace spherical_robots::conversions
