#pragma once
// The terrain and roller stacks' messages (Moazami et al.): drive rates as actuator JointStates,
// TerrainState, TrackingError, and the path and surface for rviz.

#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/Marker.h>

#include <string>

#include "spherical_robots/TerrainState.h"
#include "spherical_robots/TrackingError.h"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/terrain/body_frame.hpp"
#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/sampled_path.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots::conversions {

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

/// The plant's state message (kept for plots, tests and bags; no controller reads it), in `frame`.
/// @param realised the rates the robot realises (TerrainKinematics::realisedRates).
spherical_robots::TerrainState toTerrainStateMsg(terrain::RobotType type, terrain::ContactModel model,
                                                 const terrain::TerrainState& state,
                                                 const terrain::ContactGeometry& geometry,
                                                 const terrain::DriveRates& realised,
                                                 const std::string& frame, const ros::Time& stamp);

/// The body's pose an Odometry message carries (fields copied: the orientation is not
/// normalised, BodyFrame::state does not need it to be).
/// @throw std::invalid_argument if a coordinate of the position is not finite or exceeds
/// max_position [m], or the orientation is not finite or not a unit quaternion (within 1e-6).
terrain::BodyPose bodyPoseFromOdometry(const nav_msgs::Odometry& msg, double max_position);

/// The RS tilt joint on joint_states (the one internal joint of a terrain robot): kTiltJoint with
/// phi [rad] and its rate [rad/s].
inline const std::string kTiltJoint = "tilt";
sensor_msgs::JointState tiltJointState(double phi, double phi_rate, const ros::Time& stamp);

/// The position of kTiltJoint in msg [rad]. @throw std::invalid_argument if it is missing, not
/// finite or of magnitude above pi/2.
double tiltFromJointState(const sensor_msgs::JointState& msg);

spherical_robots::TrackingError toTrackingErrorMsg(const terrain::TrackingError& error,
                                                   const terrain::DesiredPoint& desired,
                                                   const std::string& frame, const ros::Time& stamp);

/// The poses of a path as the core's stamped points in the fixed frame: each position mapped by
/// `to_fixed` (the path's frame in the fixed frame) and its (x, y) kept; orientations and heights
/// play no part (the path is lifted onto the surface, the heading follows it).
/// @throw std::invalid_argument naming the pose whose frame_id is neither empty nor the path's,
/// or whose position is not finite or has a coordinate beyond max_position [m].
std::vector<terrain::StampedPoint> stampedPointsFromPath(const nav_msgs::Path& msg,
                                                         const Eigen::Isometry3d& to_fixed,
                                                         double max_position);

// --- Visualisation ------------------------------------------------------------------------------

/// The path over its duration() lifted onto the surface, `samples` poses (one lap of a closed
/// path, closing the loop).
/// @throw std::invalid_argument if samples < 2.
nav_msgs::Path sampledPath(const terrain::ReferencePath& path, const terrain::Surface& surface,
                           int samples, const std::string& frame, const ros::Time& stamp);

/// The surface over the rectangle `area` [m] as a TRIANGLE_LIST mesh with a grid spacing of at
/// most `resolution` [m] (the rectangle's sides divided evenly), coloured by height.
/// @throw std::invalid_argument on an empty or non-finite rectangle, a non-positive or non-finite
/// resolution, or more than 1000 cells a side.
visualization_msgs::Marker surfaceMesh(const terrain::Surface& surface,
                                       const Eigen::AlignedBox2d& area, double resolution,
                                       const std::string& frame, const ros::Time& stamp);

}  // namespace spherical_robots::conversions
