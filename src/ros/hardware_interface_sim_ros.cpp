#include "spherical_robots/ros/hardware_interface_sim_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "spherical_robots/config/hardware_interface_config.hpp"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/shared_message.hpp"

namespace spherical_robots {

namespace {

bool isEffortActuator(const hardware::SimulatedActuators& actuators, const std::string& name) {
  const auto& names = actuators.names();
  const auto it = std::find(names.begin(), names.end(), name);
  return it != names.end() &&
         actuators.limits()[it - names.begin()].kind == hardware::ActuatorKind::Effort;
}

/// The set-point of each actuator msg names: velocity[k] for a velocity actuator, effort[k] for
/// an effort actuator. @return the reason if an array is too short for the names, else empty.
std::string setpointsOf(const sensor_msgs::JointState& msg,
                        const hardware::SimulatedActuators& actuators,
                        std::vector<double>& setpoints) {
  setpoints.clear();
  for (std::size_t k = 0; k < msg.name.size(); ++k) {
    const bool effort = isEffortActuator(actuators, msg.name[k]);
    const std::vector<double>& values = effort ? msg.effort : msg.velocity;
    if (k >= values.size()) {
      std::ostringstream reason;
      reason << "command has " << msg.name.size() << " names but " << values.size()
             << (effort ? " efforts" : " velocities");
      return reason.str();
    }
    setpoints.push_back(values[k]);
  }
  return {};
}

}  // namespace

HardwareInterfaceSimRos::HardwareInterfaceSimRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(config::loadHardwareInterfaceSimParameters(RosParameterSource(pnh))),
      actuators_(config::makeSimulatedActuators(parameters_)),
      command_input_(nh.resolveName("actuators/command"), actuators_.commandTimeout()),
      clock_(parameters_.max_clock_step),
      state_rate_(nh.resolveName("actuators/state"), parameters_.rate,
                  loadRateTolerance(RosParameterSource(pnh)), [this] { return now(); }),
      updater_(nh, pnh, pnh.getNamespace()) {
  const double rate = parameters_.rate;
  updater_.setHardwareID("simulated");
  updater_.add("actuators", this, &HardwareInterfaceSimRos::diagnose);
  state_rate_.addTo(updater_);
  diagnostics_timer_ = startDiagnostics(nh, updater_);

  state_pub_ = nh.advertise<sensor_msgs::JointState>("actuators/state", kLoopQueueSize);
  command_sub_ =
      nh.subscribe("actuators/command", kLoopQueueSize, &HardwareInterfaceSimRos::commandCallback, this);
  e_stop_sub_ = nh.subscribe("estop", 10, &HardwareInterfaceSimRos::eStopCallback, this);
  if (isLockstepParticipant(nh, pnh)) {
    lockstep_ = std::make_unique<LockstepParticipant>(
        nh, pnh, std::vector<ros::Subscriber>{command_sub_}, [this, rate](const ros::Time& now) {
          update(now);
          return LockstepParticipant::Done{{state_pub_.getTopic()}, now + ros::Duration(1.0 / rate)};
        });
  } else {
    // A ros::Timer (not a WallTimer) so the actuators follow simulated time under /use_sim_time.
    timer_ =
        nh.createTimer(ros::Duration(1.0 / rate), &HardwareInterfaceSimRos::timerCallback, this);
    timer_guard_ = std::make_unique<TimerJumpGuard>(
        nh, std::vector<std::pair<ros::Timer*, double>>{{&timer_, 1.0 / rate}}, clock_.maxStep());
  }

  reconfigure_ = std::make_unique<
      dynamic_reconfigure::Server<spherical_robots::HardwareInterfaceSimConfig>>(pnh);
  reconfigure_->setCallback(
      [this](spherical_robots::HardwareInterfaceSimConfig& config, std::uint32_t level) {
        onReconfigure(config, level);
      });

  const auto& limits = actuators_.limits().front();
  ROS_INFO("hardware_interface_sim: %zu actuators, |velocity| <= %g rad/s, |accel| <= %g rad/s^2, "
           "command timeout %g s, publishing %s at %g Hz",
           actuators_.names().size(), limits.max_velocity, limits.max_acceleration,
           actuators_.commandTimeout(), state_pub_.getTopic().c_str(), rate);
  for (std::size_t i = 0; i < actuators_.names().size(); ++i) {
    if (actuators_.limits()[i].kind == hardware::ActuatorKind::Effort)
      ROS_INFO("hardware_interface_sim: actuator %s takes effort set-points, |effort| <= %g",
               actuators_.names()[i].c_str(), actuators_.limits()[i].max_effort);
    const auto& model = actuators_.models()[i];
    if (model.time_constant > 0.0 || model.dead_time > 0.0 || model.position_resolution > 0.0 ||
        model.velocity_noise > 0.0)
      ROS_INFO("hardware_interface_sim: actuator %s: time constant %g s, dead time %g s, "
               "position resolution %g rad, velocity noise %g rad/s",
               actuators_.names()[i].c_str(), model.time_constant, model.dead_time,
               model.position_resolution, model.velocity_noise);
  }
}

void HardwareInterfaceSimRos::commandCallback(
    const ros::MessageEvent<sensor_msgs::JointState const>& event) {
  const sensor_msgs::JointState::ConstPtr msg = event.getConstMessage();
  // The watchdog counts from arrival, not from header.stamp: many publishers leave it zero. In
  // lock-step a command stamped within the step it arrives in counts from its stamp, whatever
  // the order the transport delivered it in (the controller's are stamped with their step).
  const ros::Time stamp = msg->header.stamp;
  const ros::Time now = lockstep_ && stamp > lockstep_->now() &&
                                (stamp - lockstep_->now()).toSec() <= parameters_.max_stamp_skew
                            ? stamp
                            : this->now();
  followClock(now);
  std::vector<double> setpoints;
  std::string reason = setpointsOf(*msg, actuators_, setpoints);
  if (reason.empty()) reason = actuators_.command(msg->name, setpoints, now.toSec());
  if (reason.empty()) {
    command_input_.accept(now);
    reported_timeout_ = false;
  } else {
    command_input_.reject(reason);  // the actuators keep the last good set-points
  }
  if (lockstep_) lockstep_->received(command_sub_.getTopic(), event);
}

void HardwareInterfaceSimRos::eStopCallback(const std_msgs::Bool::ConstPtr& msg) {
  if (msg->data == actuators_.eStopped()) return;
  const ros::Time now = this->now();
  followClock(now);
  actuators_.setEStop(msg->data, now.toSec());
  if (msg->data)
    ROS_ERROR("hardware_interface_sim: e-stop engaged: actuators stopped, commands rejected");
  else
    ROS_WARN("hardware_interface_sim: e-stop released: actuators at rest until the next command");
  // Say so at once rather than at the next tick: this is the safety path.
  publishState(now);
  updater_.force_update();
}

void HardwareInterfaceSimRos::timerCallback(const ros::TimerEvent& event) {
  timer_guard_->observe(event);
  update(ros::Time::now());
}

ros::Time HardwareInterfaceSimRos::now() const { return workingTime(lockstep_.get()); }

void HardwareInterfaceSimRos::update(const ros::Time& now) {
  followClock(now);
  actuators_.update(now.toSec());
  if (actuators_.timedOut() && !reported_timeout_) {
    if (actuators_.timedOutAtRest())
      ROS_INFO("hardware_interface_sim: no command for %g s after one to rest: idle",
               actuators_.commandTimeout());
    else
      ROS_WARN("hardware_interface_sim: no command for %g s: actuators brought to rest",
               actuators_.commandTimeout());
    reported_timeout_ = true;
  }
  publishState(now);
}

void HardwareInterfaceSimRos::followClock(const ros::Time& now) {
  const ClockStep step = clock_.observe(now.toSec());
  if (step != ClockStep::kJumpForward && step != ClockStep::kJumpBack) return;
  const double from = actuators_.now();
  actuators_.rebase(now.toSec());
  if (timer_guard_) timer_guard_->reset();
  ROS_WARN_STREAM("hardware_interface_sim: ROS time jumped from " << from << " to " << now.toSec()
                  << " s (" << toString(step) << ", more than max_clock_step " << clock_.maxStep()
                  << " s): continuing from the new time, no time taken as elapsed");
}

void HardwareInterfaceSimRos::onReconfigure(spherical_robots::HardwareInterfaceSimConfig& config,
                                            std::uint32_t /*level*/) {
  std::vector<hardware::ActuatorLimits> limits = actuators_.limits();
  const auto velocity_actuator =
      std::find_if(limits.begin(), limits.end(), [](const hardware::ActuatorLimits& l) {
        return l.kind == hardware::ActuatorKind::Velocity;
      });
  for (hardware::ActuatorLimits& l : limits) {
    if (l.kind != hardware::ActuatorKind::Velocity) continue;
    l.max_velocity = config.max_velocity;
    l.max_acceleration = config.max_acceleration;
  }
  const bool unchanged =
      config.command_timeout == actuators_.commandTimeout() &&
      std::equal(limits.begin(), limits.end(), actuators_.limits().begin(),
                 [](const hardware::ActuatorLimits& a, const hardware::ActuatorLimits& b) {
                   return a.max_velocity == b.max_velocity &&
                          a.max_acceleration == b.max_acceleration;
                 });
  // The server's first call hands back the start-up values: applying them would be no change
  // but an extra update, which a run compared with its batch twin must not have.
  if (unchanged) return;
  const ros::Time now = this->now();
  followClock(now);
  try {
    actuators_.setLimits(limits, config.command_timeout, now.toSec());
  } catch (const std::invalid_argument& e) {
    reconfigure_problem_ = e.what();
    ROS_ERROR_STREAM("hardware_interface_sim: reconfiguration refused, the last good limits kept: "
                     << e.what());
    if (velocity_actuator != limits.end()) {
      const hardware::ActuatorLimits& kept = actuators_.limits()[velocity_actuator - limits.begin()];
      config.max_velocity = kept.max_velocity;
      config.max_acceleration = kept.max_acceleration;
    }
    config.command_timeout = actuators_.commandTimeout();
    updater_.force_update();
    return;
  }
  ROS_INFO("hardware_interface_sim: reconfigured: |velocity| <= %g rad/s, |accel| <= %g rad/s^2, "
           "command timeout %g s",
           config.max_velocity, config.max_acceleration, config.command_timeout);
}

void HardwareInterfaceSimRos::publishState(const ros::Time& stamp) {
  // The measurement (quantised, noisy if so configured), not the true state.
  state_pub_.publish(shared(conversions::jointState(
      actuators_.names(), actuators_.measuredPositions(), actuators_.measuredVelocities(),
      actuators_.efforts(), stamp)));
  state_rate_.tick();
}

void HardwareInterfaceSimRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  using diagnostic_msgs::DiagnosticStatus;
  if (actuators_.eStopped())
    status.summary(DiagnosticStatus::ERROR, "e-stop engaged");
  else if (actuators_.timedOutAtRest())
    status.summary(DiagnosticStatus::OK, "idle: at rest as last commanded");
  else if (actuators_.timedOut())
    status.summary(DiagnosticStatus::WARN, "command timeout: actuators brought to rest");
  else if (!actuators_.hasCommand())
    status.summary(DiagnosticStatus::OK, "waiting for the first command");
  else
    status.summary(DiagnosticStatus::OK, "following commands");
  // Not command_input_.report(): its key names and its WARN before the first command are not
  // this node's (docs/hardware_interface.md); the watchdog decides staleness.
  status.add("accepted commands", command_input_.accepted());
  status.add("rejected commands", command_input_.rejected());
  const std::string& reason = command_input_.lastReason();
  status.add("last rejection", reason.empty() ? std::string("none") : reason);
  command_input_.reportRejections(status);
  status.add("clock jumps", clock_.jumps());
  status.add("last refused reconfiguration",
             reconfigure_problem_.empty() ? std::string("none") : reconfigure_problem_);
  status.add("command timeout [s]", actuators_.commandTimeout());
  status.add("command age [s]", actuators_.commandAge());
  for (std::size_t i = 0; i < actuators_.names().size(); ++i) {
    const std::string& name = actuators_.names()[i];
    if (actuators_.limits()[i].kind == hardware::ActuatorKind::Effort)
      status.addf(name + " set-point, effort [N m or N]", "%.6g, %.6g", actuators_.setpoints()[i],
                  actuators_.efforts()[i]);
    else
      status.addf(name + " set-point, velocity [rad/s]", "%.6g, %.6g", actuators_.setpoints()[i],
                  actuators_.velocities()[i]);
    status.add(name + " saturated set-points", actuators_.saturations()[i]);
  }
}

}  // namespace spherical_robots
