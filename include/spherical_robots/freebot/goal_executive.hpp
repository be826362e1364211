#pragma once
// The life of a FreeBOT goal, decided with time as a number: IK from the measured chain (section
// III-B), every joint driven to the solution's contact point by its trolley (section IV-C2 in
// closed loop), arrival judged on B_n's pose, IK again from the reached state when the contact
// points are reached but the pose is not (unequal radii: the orientation depends on the path),
// abort when the re-plans are used up or the goal times out. No ROS.

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/freebot/freebot_chain.hpp"
#include "spherical_robots/freebot/src_inverse_kinematics.hpp"

namespace spherical_robots::freebot {

/// A goal's status; each change is one GoalVerdict. The codes of action/MoveFreebot.action, in
/// its order.
enum class GoalStatus {
  Moving,       ///< IK solved; the trolleys drive the joints to the solution
  Arrived,      ///< B_n within the goal tolerances
  Unreachable,  ///< IK found no pose within its tolerances: nothing moves
  Rejected,     ///< malformed: never planned
  Preempted,    ///< canceled, or replaced by a newer goal: the wheels stop
  Aborted,      ///< re-plans used up, or the timeout
};

/// "moving", "arrived", "unreachable", "rejected", "preempted", "aborted".
const char* toString(GoalStatus status);

/// B_n's desired pose in the inertial frame.
struct GoalPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();                ///< [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< unit; unused PositionOnly
  IkMode mode = IkMode::FullPose;
};

/// The errors of a verdict that measured nothing (Rejected): −1, not NaN.
constexpr double kNotMeasured = -1.0;

/// One change of a goal's status, or (ExecutiveStep::progress) where a moving goal stands.
struct GoalVerdict {
  GoalStatus status = GoalStatus::Moving;
  /// [m] B_n's distance to the goal: of the IK solution (a verdict Moving, Unreachable), of the
  /// measured chain (Arrived, Preempted, Aborted, and every progress); kNotMeasured otherwise.
  double position_error = kNotMeasured;
  double orientation_error = kNotMeasured;  ///< [rad] likewise; 0 for a position-only goal
  double elapsed = 0.0;                     ///< [s] since the goal was accepted
  int replans = 0;                          ///< IK solved again from a reached state, so far
  std::string message;                      ///< for a person: what happened and why
};

struct GoalExecutiveParameters {
  IkOptions ik;         ///< the solver's; mode is each goal's own
  TrolleyGains gains;   ///< eqs 56, 57, 63
  DriveLimits limits;   ///< of FreebotChain::drive
  double position_tolerance = 1e-4;     ///< [m] arrival: ‖r^d − r_{B_n}‖ <= this
  double orientation_tolerance = 1e-3;  ///< [rad] arrival: angle between q^d and q_{B_n} <= this
  int max_replans = 3;                  ///< IK solved again from the reached state, at most
  double timeout = 120.0;               ///< [s] from acceptance to arrival, at most
};

/// What one step asks of the chain.
struct ExecutiveStep {
  /// The joint states being driven to (the goal's IK solution); empty without a goal in force.
  std::vector<SrcJointState> joint_targets;
  std::vector<WheelSpeeds> wheels;    ///< [rad/s] every module's; zero unless driving to a goal
  std::vector<GoalVerdict> verdicts;  ///< the goal's changes of status at this step, in order
  /// The goal still in force after this step (Moving): its errors as measured at this step and
  /// the message of its latest plan; none without one.
  std::optional<GoalVerdict> progress;
};

class GoalExecutive {
 public:
  /// @throw std::invalid_argument naming the parameter unless the tolerances and the timeout are
  /// finite and > 0 and max_replans >= 0.
  GoalExecutive(FreebotChain chain, const GoalExecutiveParameters& parameters);

  /// Takes a goal at time t [ns]: IK seeded with the last measured joints. Returns its verdict:
  /// Moving, or Unreachable (the chain holds its pose). A goal in force is ended by cancel()
  /// first. @throw std::invalid_argument, with nothing changed, before any measurement, on a
  /// non-finite position or a non-unit orientation of a FullPose goal; std::logic_error while a
  /// goal is in force.
  GoalVerdict accept(const GoalPose& goal, Nanoseconds t);

  /// Ends the goal in force at time t [ns] (canceled, or about to be replaced): Preempted, with
  /// B_n's errors to it as last measured. The next step() commands every wheel to rest.
  /// @throw std::logic_error without a goal in force.
  GoalVerdict cancel(Nanoseconds t);

  /// One control step at time t [ns] from the measured chain: the wheel set-points and the goal's
  /// verdicts. @throw std::invalid_argument, with nothing changed, unless measurement fits the
  /// chain (ChainState's counts, unit joint states, finite headings).
  ExecutiveStep step(Nanoseconds t, const ChainState& measurement);

  bool active() const { return goal_.has_value(); }
  const FreebotChain& chain() const { return chain_; }
  const GoalExecutiveParameters& parameters() const { return parameters_; }
  /// The last measurement step() took, if any.
  const std::optional<ChainState>& measurement() const { return measurement_; }
  /// Every module's drive at the last step with a goal (arc left, heading error).
  const std::vector<ModuleDrive>& drives() const { return drives_; }

 private:
  struct ActiveGoal {
    GoalPose pose;
    Nanoseconds accepted = 0;
    std::vector<SrcJointState> targets;  ///< the IK solution being driven to
    int replans = 0;
    std::string plan;  ///< the message of the latest plan
  };

  /// IK for goal from the last measurement: Moving (targets set) or Unreachable.
  GoalVerdict plan(ActiveGoal& goal, Nanoseconds t, const std::string& why) const;
  /// B_n's position [m] and orientation [rad] errors to the goal in force, as measured.
  std::pair<double, double> errors() const;
  /// Ends the goal in force with status; its errors as measured now.
  GoalVerdict finish(GoalStatus status, const std::string& why, Nanoseconds t);
  /// The goal in force as measured now (Moving): ExecutiveStep::progress.
  GoalVerdict progress(Nanoseconds t) const;

  FreebotChain chain_;
  GoalExecutiveParameters parameters_;
  std::optional<ChainState> measurement_;
  std::optional<ActiveGoal> goal_;
  std::vector<ModuleDrive> drives_;
};

}  // namespace spherical_robots::freebot
