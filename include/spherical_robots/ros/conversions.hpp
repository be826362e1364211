#pragma once
// Where core types become ROS messages and back: the standard messages here, each paper's own in
// its <area>_conversions.hpp. Nodes call these and never build a message field by field; every
// function that reads a message validates it and throws std::invalid_argument saying which field
// is wrong, so a node can log, count and ignore it.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <geometry_msgs/Point.h>
#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/time.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/Marker.h>

#include <string>
#include <vector>

#include "spherical_robots/config/odometry_parameters.hpp"
#include "spherical_robots/core/simulated_sensors.hpp"
#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/terrain/teleop.hpp"

namespace spherical_robots {

/// REP 105's root, shared by every stack on a master: each stack's <prefix>odom (the FreeBOT's
/// base) is a static child of it (PlantLoop).
inline const std::string kMapFrame = "map";

/// A ROS time as the core's whole nanoseconds (core/stamp.hpp), which its decisions take.
inline Nanoseconds nanosecondsOf(const ros::Time& t) { return static_cast<Nanoseconds>(t.toNSec()); }

/// The core's whole nanoseconds as a ROS time.
inline ros::Time timeOf(Nanoseconds ns) {
  ros::Time t;
  t.fromNSec(static_cast<std::uint64_t>(ns));
  return t;
}

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

/// The transform as an isometry (a point in the child frame -> the same point in the parent's).
/// @throw std::invalid_argument naming `field` as fromVector3 and fromQuaternion.
Eigen::Isometry3d fromTransform(const geometry_msgs::Transform& transform, const std::string& field);

geometry_msgs::TransformStamped toTransform(const Eigen::Vector3d& translation,
                                            const Eigen::Quaterniond& rotation,
                                            const std::string& parent, const std::string& child,
                                            const ros::Time& stamp);

geometry_msgs::PointStamped toPointStamped(const Eigen::Vector3d& p, const std::string& frame,
                                           const ros::Time& stamp);

geometry_msgs::PoseStamped toPoseStamped(const Eigen::Vector3d& position,
                                         const Eigen::Quaterniond& orientation,
                                         const std::string& frame, const ros::Time& stamp);

/// REP 105 odometry, every field copied as given: the pose of `child` in `frame` (the orientation
/// not normalised, so that a reader sees the very doubles the core computed), its twist in
/// `child`'s axes, and the covariance diagonals of `odometry`.
nav_msgs::Odometry bodyOdometry(const BodyMotion& motion, const config::OdometryParameters& odometry,
                                const std::string& frame, const std::string& child,
                                const ros::Time& stamp);

/// An IMU's reading in `frame` (the body's), with the covariance diagonals of `odometry`.
sensor_msgs::Imu toImu(const ImuReading& reading, const config::OdometryParameters& odometry,
                       const std::string& frame, const ros::Time& stamp);

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

/// The position of each named joint in msg, as velocitiesByName, bounded by max_position.
std::vector<double> positionsByName(const sensor_msgs::JointState& msg,
                                    const std::vector<std::string>& names, double max_position);

/// A JointState with these names and values (an empty list: the message leaves that field empty).
sensor_msgs::JointState jointState(const std::vector<std::string>& names,
                                   const std::vector<double>& positions,
                                   const std::vector<double>& velocities,
                                   const std::vector<double>& efforts, const ros::Time& stamp);

/// A JointState with these names and velocities [rad/s] (no positions, no efforts).
sensor_msgs::JointState velocityJointState(const std::vector<std::string>& names,
                                           const std::vector<double>& velocities,
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

/// Message (x, y, z, w) -> Eigen (w, x, y, z), coefficients copied.
/// @throw std::invalid_argument naming `field` if a coefficient is not finite or
/// |‖q‖ − 1| > tolerance.
Eigen::Quaterniond checkedQuaternion(const geometry_msgs::Quaternion& q, const std::string& field,
                                     double tolerance = 1e-6);

/// checkedQuaternion, normalised.
Eigen::Quaterniond fromQuaternion(const geometry_msgs::Quaternion& q, const std::string& field,
                                  double tolerance = 1e-6);

/// A marker in `frame`, added, opaque, with the identity pose: the caller sets its shape.
visualization_msgs::Marker marker(const std::string& ns, int id, int type, const std::string& frame,
                                  const ros::Time& stamp);

}  // namespace spherical_robots::conversions
