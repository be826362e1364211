#pragma once
// The FreeBOT stack's messages: wheel speeds as actuator JointStates, FreebotState, and the
// move_freebot action's goals, feedback and results.

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstddef>
#include <string>
#include <vector>

#include "spherical_robots/FreebotState.h"
#include "spherical_robots/MoveFreebotAction.h"
#include "spherical_robots/freebot/freebot_chain.hpp"
#include "spherical_robots/freebot/goal_executive.hpp"
#include "spherical_robots/ros/conversions.hpp"

namespace spherical_robots::conversions {

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

/// The goal a target asks for: B_n's pose in `frame` (or an empty frame_id); an all-zero
/// orientation asks for the position only, another one must be unit within `unit_tolerance`.
/// @throw std::invalid_argument naming the field: another frame, a coordinate not finite or
/// beyond max_distance [m], a quaternion not finite or not unit.
freebot::GoalPose goalPoseFromMsg(const geometry_msgs::PoseStamped& target, const std::string& frame,
                                  double max_distance, double unit_tolerance);

/// The result of a goal that ended with `verdict` (not Moving).
spherical_robots::MoveFreebotResult toMoveFreebotResult(const freebot::GoalVerdict& verdict);
/// The feedback of a moving goal (ExecutiveStep::progress).
spherical_robots::MoveFreebotFeedback toMoveFreebotFeedback(const freebot::GoalVerdict& progress);

/// The tf frame of sphere B_i (i = 0: the fixed base): "<prefix>link<i>".
std::string freebotLinkFrame(const std::string& prefix, std::size_t i);

/// The chain on tf: per joint i B_{i-1} -> B_i (B_0, the fixed base, is under map: PlantLoop).
std::vector<geometry_msgs::TransformStamped> freebotChainTransforms(
    const freebot::SrcManipulator& manipulator, const freebot::ChainState& state,
    const std::string& prefix, const ros::Time& stamp);

/// Per sphere B_i a sphere of radius l_i in its frame (the base grey), and per trolley an arrow
/// at its contact point, heading φ_i in the contact plane P_i, in B_{i-1}'s frame.
visualization_msgs::MarkerArray freebotChainMarkers(const freebot::SrcManipulator& manipulator,
                                                    const freebot::ChainState& state,
                                                    const std::string& prefix,
                                                    const ros::Time& stamp);

}  // namespace spherical_robots::conversions
