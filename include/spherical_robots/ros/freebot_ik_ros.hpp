#pragma once
// The freebot_ik node: IK of a FreeBOT chain as a service (core solveIk), and goals that move the
// chain: IK from the current state, then every joint driven to its solution by its trolley
// (core FreebotChain::drive, section IV-C2) through the wheel actuators of the hardware interface.

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "spherical_robots/FreebotGoalResult.h"
#include "spherical_robots/FreebotState.h"
#include "spherical_robots/SolveFreebotIk.h"
#include "spherical_robots/freebot/freebot_chain.hpp"
#include "spherical_robots/freebot/src_inverse_kinematics.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

namespace spherical_robots {

/// Parameters (private, ~): ik/{position_tolerance [m] (1e-5), orientation_tolerance [rad] (1e-4),
/// restarts (60), max_iterations (100)}: the solver's (docs/conventions.md, "FreeBOT IK");
/// goal_position_tolerance [m] (1e-4), goal_orientation_tolerance [rad] (1e-3): arrival of a goal;
/// max_forward_speed [m/s] (0.02), max_steering_speed [rad/s] (2), max_wheel_speed [rad/s] (10),
/// heading_tolerance [rad] (0.05), contact_tolerance [m] (2e-6), steering_distance [m] (1e-3):
/// the drive (core DriveLimits); max_replans (3): IK again from the reached state when the
/// contact points are reached but the pose is not (unequal radii); goal_timeout [s] (120);
/// max_stamp_skew [s] (1): a freebot_state stamped further from the clock, or at 0, is rejected;
/// max_goal_distance [m] (100): a goal coordinate beyond it is rejected (REJECTED), not planned;
/// input_timeout [s] (0.1) of freebot_state. In the node handle's namespace: the chain
/// (freebotChainFromParams).
/// Subscribes freebot_state and goal (geometry_msgs/PoseStamped in "world" or ""; an all-zero
/// orientation asks for the position only). Publishes, for every good state, actuators/command
/// (the wheel speeds of every module [rad/s]: zeros when idle, so the hardware's watchdog never
/// fires while the node lives); goal_result (FreebotGoalResult, latched) on each change of a
/// goal's status; ik_target (the goal, latched); /diagnostics. Serves solve_ik (SolveFreebotIk).
/// An unreachable goal (IK unsuccessful) moves nothing: the chain holds its pose.
class FreebotIkRos {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  FreebotIkRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  struct Goal {
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    freebot::IkMode mode;
    geometry_msgs::Pose pose;
    ros::Time received;
    std::vector<freebot::SrcJointState> targets;  ///< the IK solution being driven to
    int replans = 0;
  };

  void onState(const spherical_robots::FreebotState& msg);
  /// Wheel speeds towards the goal (or zero) from one state (nothing for a rejected one).
  void drive(const spherical_robots::FreebotState& msg);
  void onGoal(const geometry_msgs::PoseStamped& msg);
  bool onSolve(spherical_robots::SolveFreebotIk::Request& request,
               spherical_robots::SolveFreebotIk::Response& response);
  /// B_n's position [m] and orientation [rad] errors to the goal (0 rad for a position-only one).
  std::pair<double, double> errorsTo(const Goal& goal) const;
  /// Solves for the goal from the current state; false (and a verdict) if unreachable.
  bool plan(Goal& goal, const ros::Time& now);
  void finish(std::uint8_t status, double position_error, double orientation_error,
              const std::string& message, const ros::Time& now);
  void publishResult(const Goal& goal, std::uint8_t status, double position_error,
                     double orientation_error, const std::string& message, const ros::Time& now);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  freebot::FreebotChain chain_;
  freebot::IkOptions ik_options_;
  freebot::TrolleyGains gains_;
  freebot::DriveLimits limits_;
  double goal_position_tolerance_;
  double goal_orientation_tolerance_;
  int max_replans_;
  double goal_timeout_;
  double max_stamp_skew_;  ///< [s] a freebot_state stamped further from the clock is rejected
  double max_goal_distance_;  ///< [m] a goal coordinate beyond it is rejected, not UNREACHABLE
  std::optional<freebot::ChainState> state_;
  std::optional<Goal> goal_;
  std::vector<freebot::ModuleDrive> last_drive_;
  spherical_robots::FreebotGoalResult last_result_;
  bool have_result_ = false;
  unsigned long goals_ = 0;
  unsigned long unreachable_ = 0;
  InputMonitor state_input_;
  InputMonitor goal_input_;
  StepPublications step_publications_;
  /// Drives from each state when it comes, or in lock-step at the step it is stamped with.
  MessageDrivenWork<spherical_robots::FreebotState> work_;
  ros::Subscriber state_sub_;
  ros::Subscriber goal_sub_;
  LoopPublisher command_pub_;
  ros::Publisher result_pub_;
  ros::Publisher target_pub_;
  ros::ServiceServer solve_server_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
};

}  // namespace spherical_robots
