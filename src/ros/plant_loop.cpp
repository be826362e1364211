#include "spherical_robots/ros/plant_loop.hpp"

#include <XmlRpcValue.h>
#include <ros/param.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

std::string rosHome() {
  if (const char* home = std::getenv("ROS_HOME")) return home;
  if (const char* home = std::getenv("HOME")) return std::string(home) + "/.ros";
  throw std::invalid_argument("checkpoint: ros_home, but neither ROS_HOME nor HOME is set");
}

/// The checkpoint file of the plant whose private handle is pnh, in `where` (~checkpoint).
std::string checkpointPath(const std::string& where, const ros::NodeHandle& pnh) {
  const std::filesystem::path directory =
      where == "ros_home" ? std::filesystem::path(rosHome()) / "checkpoints" : std::filesystem::path(where);
  std::filesystem::create_directories(directory);
  std::string name = pnh.getNamespace().substr(1);
  std::replace(name.begin(), name.end(), '/', '.');
  return (directory / (name + ".checkpoint")).string();
}

/// The parameter's value as XML-RPC text ("none" if unset), for the fingerprint.
std::string parameterText(const std::string& name) {
  XmlRpc::XmlRpcValue value;
  return ros::param::get(name, value) ? value.toXml() : "none";
}

}  // namespace

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
  const ros::Time resume_at = resume();
  clock_ = makePlantClock(nh_, pnh_, parameters_,
                          [this](const ros::Time& now) { return tick(now); }, state.publisher(),
                          actuator_sub_);
  if (!resume_at.isZero()) clock_->resumeAt(resume_at);
  updater_.setHardwareID(defaults_.hardware_id);
  updater_.add(defaults_.task, this, &PlantLoop::diagnose);
  state_rate_->addTo(updater_);
  diagnostics_timer_ = startDiagnostics(nh_, updater_);
}

ros::Time PlantLoop::resume() {
  if (parameters_.checkpoint == "none") return {};
  if (!model_->checkpointState()) {
    ROS_WARN_STREAM("~checkpoint " << parameters_.checkpoint << ": this plant (" << defaults_.task
                                   << ") keeps no checkpoint; a restart starts afresh");
    return {};
  }
  if (!ros::param::get("/run_id", checkpoint_key_.run_id)) {
    ROS_WARN_STREAM("~checkpoint " << parameters_.checkpoint << ": no /run_id (not started by "
                                   "roslaunch), so no checkpoint is kept");
    return {};
  }
  std::string description = defaults_.task + "\n" + parameterText(pnh_.getNamespace());
  for (const std::string& name : model_->sharedParameters())
    description += "\n" + name + " " + parameterText(nh_.resolveName(name));
  checkpoint_key_.fingerprint = fingerprintOf(description);
  ResumeDecision decision;
  std::string path;
  try {
    path = checkpointPath(parameters_.checkpoint, pnh_);
    decision = decideResume(path, checkpoint_key_);
    checkpoint_.emplace(path);
  } catch (const std::exception& e) {  // a directory or file that cannot be made: run without
    ROS_ERROR_STREAM("~checkpoint " << parameters_.checkpoint << ": " << e.what()
                                    << "; no checkpoint is kept, a restart starts afresh");
    return {};
  }
  if (!decision.checkpoint) {
    ROS_INFO_STREAM("Starting afresh, keeping a checkpoint in " << path << " ("
                                                                << decision.reason << ")");
    return {};
  }
  try {
    model_->resumeState(decision.checkpoint->state);
  } catch (const std::invalid_argument& e) {
    ROS_ERROR_STREAM("Starting afresh: the checkpoint " << path << " is no state of "
                                                        << "this model: " << e.what());
    return {};
  }
  ros::Time start, time;
  start.fromNSec(decision.checkpoint->start);
  time.fromNSec(decision.checkpoint->time);
  timeline_.resume(start, time);
  ROS_INFO_STREAM("Resuming from the checkpoint " << path << " at " << time
                                                  << " s, " << model_->describeState());
  return time;
}

void PlantLoop::writeCheckpoint(const ros::Time& now) {
  try {
    checkpoint_->write({checkpoint_key_, timeline_.start(),
                                            nanosecondsOf(now), *model_->checkpointState()});
  } catch (const std::runtime_error& e) {
    ++checkpoint_failures_;
    ROS_ERROR_STREAM_THROTTLE(1.0, e.what());
  }
}

void PlantLoop::onActuatorState(const ros::MessageEvent<sensor_msgs::JointState const>& event) {
  const sensor_msgs::JointState& msg = *event.getConstMessage();
  // In a nodelet manager a message may come while start() is still making the clock.
  if (!clock_) return;
  try {
    model_->read(msg);
    actuator_input_.accept(clock_->now());
  } catch (const std::invalid_argument& e) {
    actuator_input_.reject(e.what());
  }
  clock_->received(actuator_sub_.getTopic(), msg.header.stamp, event.getPublisherName());
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
  if (std::find(published.begin(), published.end(), state_topic_) != published.end()) {
    state_rate_->tick();
    if (checkpoint_) writeCheckpoint(now);
  }
  return published;
}

void PlantLoop::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  model_->diagnose(status);
  const ros::Time now = clock_->now();
  clock_->report(status);
  timeline_.report(status, now);
  actuator_input_.report(status, now);
  if (checkpoint_) {
    status.add("checkpoint", checkpoint_->path());
    status.add("checkpoint write failures", checkpoint_failures_);
    if (checkpoint_failures_ > 0)
      status.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN,
                          "checkpoint not written: a restart would not resume");
  }
}

}  // namespace spherical_robots
