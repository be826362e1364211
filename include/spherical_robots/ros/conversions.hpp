#pragma once
// The one place where core types become ROS messages and back. Nodes call these and never build
// a message field by field; every function that reads a message validates it and throws
// std::invalid_argument saying which field is wrong, so a node can log, count and ignore it.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <geometry_msgs/Point.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/time.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/Marker.h>

#include <string>
#include <vector>

#include "spherical_robots/FreebotGoalResult.h"
#include "spherical_robots/FreebotState.h"
#include "spherical_robots/TerrainState.h"
#include "spherical_robots/TrackingError.h"
#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/freebot/freebot_chain.hpp"
#include "spherical_robots/freebot/goal_executive.hpp"
#include "spherical_robots/terrain/teleop.hpp"
#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots {

/// The fixed frame of every plant and controller.
inline const std::string kWorldFrame = "world";

/// A ROS time as the core's whole nanoseconds (core/stamp.hpp), which its decisions take.
inline Nanoseconds nanosecondsOf(const ros::Time& t) { return static_cast<Nanoseconds>(t.toNSec()); }

}  // namespace spherical_robots

namespace spherical_robots::conversions {

// --- Eigen <-> geometry_msgs -----------------------------------------------------------------

geometry_msgs::Point toPoint(const Eigen::Vector3d& p);
geometry_msgs::Vector3 toVector3(const Eigen::Vector3d& v);
/// Eigen (w, x, y, z) -> message (x, y, z, w), normalised.
geometry_msgs::Quaternion toQuaternion(const Eigen::Quaterniond& q);
/// @throw std::invalid_argument naming `field` if a coordinate is not finite.
Eigen::Vector3d fromPoint(const geometry_msgs::Point& p, const std::string& field);
Eigen::Vector3d fromVector3(const geometry_msgs::Vector3& v, const std::string& field);
/// As fromPoint and fromVector3, and @throw std::invalid_argument naming `field` if a coordinate's
/// magnitude exceeds max_magnitude (plausibility: 1e300 is finite, and overflows on).
Eigen::Vector3d boundedPoint(const geometry_msgs::Point& p, const std::string& field,
                             double max_magnitude);
Eigen::Vector3d boundedVector3(const geometry_msgs::Vector3& v, const std::string& field,
                               double max_magnitude);

geometry_msgs::TransformStamped toTransform(const Eigen::Vector3d& translation,
                                            const Eigen::Quaterniond& rotation,
                                            const std::string& parent, const std::string& child,
                                            const ros::Time& stamp);

geometry_msgs::PoseStamped toPoseStamped(const Eigen::Vector3d& position,
                                         const Eigen::Quaterniond& orientation,
                                         const std::string& frame, const ros::Time& stamp);

/// Pose of `child` in `frame` and its twist, REP 105 style: the twist is expressed in `child`.
/// @param linear_velocity, angular_velocity [m/s], [rad/s] in the world (`frame`) axes.
nav_msgs::Odometry toOdometry(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                              const Eigen::Vector3d& linear_velocity,
                              const Eigen::Vector3d& angular_velocity, const std::string& frame,
                              const std::string& child, const ros::Time& stamp);

// --- Drive rates <-> actuators -----------------------------------------------------------------

/// The velocity [rad/s] of each named actuator in msg, in the order of names (others ignored).
/// @throw std::invalid_argument naming the problem: fewer velocities than names in msg, a name
/// missing, a velocity not finite or of magnitude above max_rate [rad/s] (no actuator's rate).
std::vector<double> velocitiesByName(const sensor_msgs::JointState& msg,
                                     const std::vector<std::string>& names, double max_rate);

/// The effort [N m or N] of each named actuator in msg, as velocitiesByName, bounded by
/// max_effort.
std::vector<double> effortsByName(const sensor_msgs::JointState& msg,
                                  const std::vector<std::string>& names, double max_effort);

/// A JointState with these names and velocities [rad/s] (no positions, no efforts).
sensor_msgs::JointState velocityJointState(const std::vector<std::string>& names,
                                           const std::vector<double>& velocities,
                                           const ros::Time& stamp);

/// Drive rates [rad/s] from the velocities of a JointState named by the type's actuators
/// (terrain::rateNames: 3R theta, phi, psi; 2R theta, phi; RT theta, psi; RS alpha, phi); rates the
/// type does not actuate are 0, names the type does not have are ignored.
/// @throw std::invalid_argument as velocitiesByName, naming the robot type.
terrain::DriveRates ratesFromJointState(terrain::RobotType type, const sensor_msgs::JointState& msg,
                                        double max_rate);

/// A JointState with the type's actuator names and their rates [rad/s] as velocities (no
/// positions, no efforts).
sensor_msgs::JointState jointStateFromRates(terrain::RobotType type, const terrain::DriveRates& rates,
                                            const ros::Time& stamp);

/// The planar part of a body twist: linear.x forward, linear.y leftward [m/s], angular.z yaw
/// rate [rad/s] (REP 103), for terrain::TeleopMapping.
struct PlanarTwist {
  terrain::VelocityRequest request;
  std::vector<std::string> ignored;  ///< non-zero fields no rolling sphere can follow
};

/// @throw std::invalid_argument on a field that is not finite or of magnitude above max_magnitude
/// [m/s or rad/s] (a person's command, not an overflow: it would drive the robot at its limits).
PlanarTwist planarTwist(const geometry_msgs::Twist& twist, double max_magnitude);

// --- Terrain state and tracking ----------------------------------------------------------------

/// The plant's state message, in frame "world".
/// @param realised the rates the robot realises (TerrainKinematics::realisedRates).
spherical_robots::TerrainState toTerrainStateMsg(terrain::RobotType type, terrain::ContactModel model,
                                                 const terrain::TerrainState& state,
                                                 const terrain::ContactGeometry& geometry,
                                                 const terrain::DriveRates& realised,
                                                 const ros::Time& stamp);

/// The contact geometry a TerrainState message describes: P0, centre, R_L = [h, n x h, n] and the
/// gradient (f_x, f_y) = -(n_x, n_y) / n_z.
/// @throw std::invalid_argument if a field is not finite, a coordinate of P0 or the centre exceeds
/// max_position [m], n or h is not a unit vector, h is not perpendicular to n, or n does not point
/// up (tolerance 1e-6).
terrain::ContactGeometry contactGeometryFromMsg(const spherical_robots::TerrainState& msg,
                                                double max_position);

spherical_robots::TrackingError toTrackingErrorMsg(const terrain::TrackingError& error,
                                                   const terrain::DesiredPoint& desired,
                                                   const std::string& frame, const ros::Time& stamp);

// --- Visualisation ------------------------------------------------------------------------------

/// One period of the path lifted onto the surface, `samples` poses (closing the loop).
/// @throw std::invalid_argument if samples < 2.
nav_msgs::Path sampledPath(const terrain::ReferencePath& path, const terrain::Surface& surface,
                           int samples, const std::string& frame, const ros::Time& stamp);

/// The surface over the square [-half_extent, half_extent]^2 [m] as a TRIANGLE_LIST mesh with a
/// grid spacing of `resolution` [m], coloured by height.
/// @throw std::invalid_argument on a non-positive or non-finite extent or resolution, or more than
/// 1000 x 1000 cells.
visualization_msgs::Marker surfaceMesh(const terrain::Surface& surface, double half_extent,
                                       double resolution, const std::string& frame,
                                       const ros::Time& stamp);

// --- FreeBOT -----------------------------------------------------------------------------------

/// Message (x, y, z, w) -> Eigen (w, x, y, z), normalised.
/// @throw std::invalid_argument naming `field` if a coefficient is not finite or
/// |‖q‖ − 1| > tolerance.
Eigen::Quaterniond fromQuaternion(const geometry_msgs::Quaternion& q, const std::string& field,
                                  double tolerance = 1e-6);

/// The wheel actuators of a chain of `modules` FreeBOT modules, in order: module1_wheel_right,
/// module1_wheel_left, module2_wheel_right, … (docs/conventions.md, "FreeBOT stack").
std::vector<std::string> freebotWheelNames(std::size_t modules);

/// Every module's wheel speeds [rad/s] from the velocities of a JointState (names as
/// freebotWheelNames, others ignored). @throw std::invalid_argument as velocitiesByName.
std::vector<freebot::WheelSpeeds> wheelSpeedsFromJointState(const sensor_msgs::JointState& msg,
                                                            std::size_t modules, double max_rate);

/// A JointState commanding these wheel speeds [rad/s] (names as freebotWheelNames).
sensor_msgs::JointState jointStateFromWheelSpeeds(const std::vector<freebot::WheelSpeeds>& wheels,
                                                  const ros::Time& stamp);

/// The chain's state message; `end` is B_n's pose in `frame`.
spherical_robots::FreebotState toFreebotStateMsg(const freebot::ChainState& state,
                                                 const freebot::LinkPose& end,
                                                 const std::string& frame, const ros::Time& stamp);

/// The chain state a FreebotState message describes (quaternions normalised).
/// @throw std::invalid_argument if the arrays differ in length, a quaternion is not unit within
/// 1e-6 or a heading is not finite or beyond 1e6 rad.
freebot::ChainState chainStateFromMsg(const spherical_robots::FreebotState& msg);

/// The verdict on a goal whose pose was `goal` (not echoed unless finite: a rejected goal may
/// hold NaN or 1e300), in `frame`.
spherical_robots::FreebotGoalResult toGoalResultMsg(const freebot::GoalVerdict& verdict,
                                                    const geometry_msgs::Pose& goal,
                                                    const std::string& frame,
                                                    const ros::Time& stamp);

}  // namespace spherical_robots::conversions
