#pragma once
// The Norma stack's messages: NormaState, the URDF's joints, the measurement odometry and
// joint_states carry, the actuators' efforts, the tracking error and the path of eq 52 for rviz.

#include <nav_msgs/Odometry.h>
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

/// The pose odometry carries, as the controller reads it: X, Y of odom's position and
/// ψ = yawOf(its orientation), in (−π, π]; q and q̇ zero. The control loop bounds the values.
/// @throw std::invalid_argument naming the field: a non-finite position, a non-finite or
/// non-unit orientation.
norma::NormaMeasurement normaPoseFromOdometry(const nav_msgs::Odometry& odom);

/// `pose` with q and q̇ of the URDF's joints on joint_states, by name (normaJointState's).
/// @throw std::invalid_argument naming the problem: a joint missing, fewer positions or
/// velocities than names, a non-finite value.
norma::NormaMeasurement withNormaJoints(norma::NormaMeasurement pose,
                                        const sensor_msgs::JointState& joints);

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
