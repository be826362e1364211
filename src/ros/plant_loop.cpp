#include "spherical_robots/ros/plant_loop.hpp"

#include <algorithm>
#include <stdexcept>

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {

PlantLoop::PlantLoop(ros::NodeHandle nh, ros::NodeHandle pnh, const Defaults& defaults)
    : nh_(nh),
      pnh_(pnh),
      defaults_(defaults),
      parameters_(config::loadPlantLoopParameters(RosParameterSource(pnh), defaults.parameters)),
      timeline_(parameters_.duration, parameters_.max_clock_step),
      actuator_input_(nh.resolveName("actuators/state"), parameters_.state_timeout),
      tf_(step_publications_),
      rate_tolerance_(loadRateTolerance(RosParameterSource(pnh))),
      updater_(nh, pnh, pnh.getNamespace()) {
  if (defaults.root_frame.empty() || defaults.root_frame == kMapFrame)
    throw std::invalid_argument("a plant's root frame must be a frame of its own under " + kMapFrame +
                                ", got '" + defaults.root_frame + "'");
  static_tf_.sendTransform(conversions::toTransform(
      {parameters_.origin_x, parameters_.origin_y, 0.0},
      Eigen::Quaterniond(Eigen::AngleAxisd(parameters_.origin_yaw, Eigen::Vector3d::UnitZ())),
      kMapFrame, defaults.root_frame, ros::Time::now()));
  if (parameters_.trail_period > 0.0)
    trail_.emplace(nh, "trail", defaults.root_frame, parameters_.trail_period, defaults.max_trail_points);
}

void PlantLoop::start(PlantModel& model, const LoopPublisher& state, double state_rate) {
  model_ = &model;
  state_topic_ = state.topic();
  state_rate_ = std::make_unique<TopicRate>(state_topic_, state_rate, rate_tolerance_,
                                            [this] { return clock_->now(); });
  actuator_sub_ = nh_.subscribe("actuators/state", kLoopQueueSize, &PlantLoop::onActuatorState, this);
  clock_ = makePlantClock(nh_, pnh_, parameters_,
                          [this](const ros::Time& now) { return tick(now); }, state.publisher(),
                          actuator_sub_);
  updater_.setHardwareID(defaults_.hardware_id);
  updater_.add(defaults_.task, this, &PlantLoop::diagnose);
  state_rate_->addTo(updater_);
  diagnostics_timer_ = startDiagnostics(nh_, updater_);
}

void PlantLoop::onActuatorState(const sensor_msgs::JointState& msg) {
  // In a nodelet manager a message may come while start() is still making the clock.
  if (!clock_) return;
  try {
    model_->read(msg);
    actuator_input_.accept(clock_->now());
  } catch (const std::invalid_argument& e) {
    actuator_input_.reject(e.what());
  }
  clock_->received(actuator_sub_.getTopic(), msg.header.stamp);
}

std::vector<std::string> PlantLoop::tick(const ros::Time& now) {
  if (timeline_.finished()) return {};
  const bool fresh = actuator_input_.fresh(now);
  timeline_.tick(now, [&](double elapsed) { model_->advance(elapsed, fresh); });
  model_->publishEveryStep(now, fresh);
  if (publication_.take(nanosecondsOf(now))) model_->publishPeriodic(now, fresh);
  if (trail_ && trail_->due(now)) {
    if (const std::optional<PlantModel::Pose> pose = model_->trailPose())
      trail_->add(now, pose->position, pose->orientation);
  }
  if (timeline_.complete(now)) {
    ROS_INFO_STREAM("scenario complete after " << timeline_.duration() << " s, "
                                               << model_->describeState());
    clock_->finish();
  }
  std::vector<std::string> published = step_publications_.take();
  if (std::find(published.begin(), published.end(), state_topic_) != published.end())
    state_rate_->tick();
  return published;
}

void PlantLoop::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  model_->diagnose(status);
  const ros::Time now = clock_->now();
  clock_->report(status);
  timeline_.report(status, now);
  actuator_input_.report(status, now);
}

}  // namespace spherical_robots
