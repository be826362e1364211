#pragma once
// The rotor_planner node: the two-rotor sphere's geometric-phase planner (Svinin et al.) as a
// service, with the chosen plan published for rviz.

#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/UInt32.h>

#include <cstdint>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "spherical_robots/PlanRotorMotion.h"
#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/trail.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/manoeuvre_correction.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"

#include "spherical_robots/ros/timer_jump_guard.hpp"

namespace spherical_robots {

/// Parameters (private, ~): sphere_radius R [m] (0.1); max_radius [m] (0.07 = 0.7 R unless set),
/// the default limit of a request's circle radii; frame_id ("odom"), the plane frame of the
/// predicted path; sphere_frame ("base_link"), the sphere's frame for the contact-curve marker;
/// samples_per_step (200).
///
/// Service ~plan (spherical_robots/PlanRotorMotion): plans with rotor::planRotorMotion; a bad
/// request is answered with success = false and the reason (logged), never a dead node. On
/// success it publishes, latched, for the shortest plan: planned_path (nav_msgs/Path in
/// frame_id: the sphere's centre and orientation along all n steps from the origin) and
/// contact_curve (visualization_msgs/Marker LINE_STRIP in sphere_frame: the figure eight on the
/// sphere's surface).
///
/// Execution (open loop: set-points from the plan only): ~execute (std_msgs/UInt32, the index of
/// a solution of the last successful ~plan, 0 = shortest) traces that plan's figure eight n times
/// from rest to rest (rotor::CurveTiming: ~curve_rate θ̇ [rad/s] (1), sin² ramps of ~ramp_time
/// [s] (1)) and streams the rotor set-points of eq 11 (rotor::planSetPointAt) every
/// 1/~command_rate [s] (100 Hz, ROS time) on actuators/command (sensor_msgs/JointState velocities
/// of rotor_1, rotor_2 [rad/s]), then one zero. If the plan's peak rotor speed at ~curve_rate
/// exceeds ~max_rotor_speed [rad/s] (0: no limit) the curve rate is lowered to fit. With
/// ~actuator_time_constant τ [s] (0) > 0 the set-points carry the feed-forward inverse of a
/// first-order actuator lag (rotor::lagCompensatedSetPoint), still open loop. Parameter
/// rotor_inertia_scale J_zz / J_r (12) in the node handle's namespace. The plan starts wherever
/// the sphere is at rest (odom, nav_msgs/Odometry of the plant): its goal is the plan's target
/// taken from there (rotor::planEnd; the zero state gives the target itself).
/// A manoeuvre at start-up: with ~manoeuvre set, the node plans ~manoeuvre/{u, v [m], psi [rad]}
/// (0), k (2.5) and steps (2) as a ~plan request would at construction
/// (no plan: construction fails, naming the reason) and executes solution ~manoeuvre/index (0)
/// from its first command period, so a lock-step run starts it at the same step every time
/// (launch/rotor_stack.launch execute:=true), unlike a request from outside the loop.
/// Closing the loop over manoeuvres: with ~corrections N (0: open loop) > 0, after each
/// execution and its ~settle [s] (1) the node measures the rest from odom and, while corrections
/// remain: if the contact is more than ~correction_tilt_tolerance [rad] (1e-4) off the sphere's
/// south pole and the last correction was not such an arc, rolls it back along
/// rotor::PoleReturnArc; else, if the sphere is more than
/// ~correction_tolerance [m] (1e-5) or ~correction_heading_tolerance [rad] (1e-3) off the goal,
/// plans a ~correction_steps (1)-step figure eight from there to the goal
/// (rotor::correctionTarget, the request's k and radius limit) and executes it the same way;
/// one the planner cannot find ends the corrections with a warning. Each counts as a correction.
/// While executing and settling it appends odom to driven_path (nav_msgs/Path, every
/// ~path_period [s] (0.05)); at the end it publishes the index on execution_done
/// (std_msgs/UInt32, latched). A request while executing, before any plan, or with a bad index
/// is refused with a warning (a request beyond rotor::kMaxSteps, kMaxHeadingTurns, ... too).
/// ~max_position [m] (1000) and ~max_stamp_skew [s] (1): an odom farther out, stamped farther
/// from the clock or at 0, or with an orientation farther than 1e-3 from unit, is rejected.
/// An odom that is not finite or upside down is ignored (logged) and
/// the last good rest pose kept. /diagnostics ("rotor planner"): executing or idle, plan and
/// correction counts, the last refused plan request or execution, the last end's miss, and the
/// odom input (stale after ~odom_timeout [s] (0.5), rejected count and reason), at least once a
/// second (wall). driven_path is labelled ~frame_id: odom is expected in that frame.
class RotorPlannerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  RotorPlannerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  bool onPlan(spherical_robots::PlanRotorMotion::Request& request,
              spherical_robots::PlanRotorMotion::Response& response);
  /// Publishes the path and marker of the plan (a, b, γ in units of R) for inertia ratio k.
  void publishPlan(double k, int steps, double a, double b, double gamma);
  void onExecute(const std_msgs::UInt32& msg);
  /// Plans ~manoeuvre (if set) and keeps its index for the first command period.
  void planStartUpManoeuvre(const ros::NodeHandle& pnh);
  /// Starts tracing `curve` over `steps` steps toward `goal`; false (logged) if it cannot.
  bool startExecution(std::uint32_t index, const rotor::FigureEight& curve, int steps,
                      const rotor::RestPose& goal, int corrections_left);
  /// Replaces the settled execution by the arc back to the pole, toward the same goal.
  bool startPoleReturn(const rotor::PoleReturnArc& arc, int corrections_left);
  rotor::CurveTiming curveTiming(int steps, double rate) const;
  /// ~curve_rate, lowered (with a warning) so that a manoeuvre whose rotors peak at
  /// peak_at_unit_rate [rad/s] at θ̇ = 1 rad/s stays within ~max_rotor_speed.
  double limitedCurveRate(double peak_at_unit_rate) const;
  /// After an execution has settled: plans and starts a correction if one is due and possible
  /// (never from a stale odom; a failure is refused, logged and reported, never thrown).
  bool startCorrection();
  bool planCorrection();
  /// How far the last good rest pose is from the goal: [m] on the plane, [rad] of heading.
  std::pair<double, double> missFrom(const rotor::RestPose& goal) const;
  /// Logs a refusal as a warning and keeps it for /diagnostics.
  void refuse(const std::string& problem);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  void onCommandTimer(const ros::TimerEvent& event);
  /// The set-point of the manoeuvre in progress at now, and what follows its end.
  void command(const ros::Time& now);
  void onOdometry(const nav_msgs::Odometry& msg);

  ros::NodeHandle nh_;
  double radius_;
  double max_radius_;
  double max_position_;    ///< [m] an odom position beyond it is rejected (plausibility)
  double max_stamp_skew_;  ///< [s] an odom stamped further from the clock, or at 0, is rejected
  ClockJumpDetector clock_;  ///< ~max_clock_step [s] (5): over a jump the manoeuvre goes on
  std::string frame_id_;
  std::string sphere_frame_;
  int samples_per_step_;
  ros::ServiceServer service_;
  ros::Publisher path_pub_;
  ros::Publisher marker_pub_;

  // Execution.
  double inertia_scale_;
  double curve_rate_;
  double ramp_time_;
  double command_period_;
  double max_rotor_speed_;
  double settle_;
  double actuator_time_constant_;
  int corrections_;
  double correction_tolerance_;
  double correction_heading_tolerance_;
  double correction_tilt_tolerance_;
  int correction_steps_;
  double plan_k_ = 0.0;
  int plan_steps_ = 0;
  double plan_max_radius_ = 0.0;          ///< [R]
  std::vector<rotor::FigureEight> plans_;  ///< the last successful request's, in units of R
  std::vector<rotor::PlanTarget> plan_targets_;  ///< what each of plans_ reaches from zero
  struct Execution {
    std::uint32_t index;
    rotor::SetPointSchedule schedule;
    double duration;  ///< [s] of the schedule, from start
    ros::Time start;
    rotor::RestPose goal;
    int corrections_left;
    bool pole_return;  ///< the arc back to the pole, not a figure eight
  };
  std::optional<Execution> execution_;
  std::optional<std::uint32_t> start_up_execute_;  ///< the start-up manoeuvre's, until it starts
  std::optional<rotor::RestPose> rest_pose_;  ///< from the latest valid odom
  Eigen::Vector2d contact_angles_ = Eigen::Vector2d::Zero();  ///< (u_o, v_o) of that odom
  InputMonitor odom_input_;
  unsigned long executions_ = 0;
  unsigned long corrections_made_ = 0;
  std::string last_problem_;
  std::optional<std::pair<double, double>> last_miss_;  ///< [m], [rad] at the last end
  diagnostic_updater::Updater updater_;
  ros::Subscriber execute_sub_;
  ros::Subscriber odom_sub_;
  StepPublications step_publications_;
  LoopPublisher command_pub_;
  Trail driven_;  ///< driven_path, latched
  ros::Publisher done_pub_;
  ros::Timer command_timer_;
  std::unique_ptr<TimerJumpGuard> timer_guard_;  ///< restarts command_timer_ after a jump
  std::unique_ptr<LockstepParticipant> lockstep_;  ///< in lock-step, instead of the timer
  ros::WallTimer diagnostics_timer_;
};

}  // namespace spherical_robots
