#pragma once
// The loop every plant node runs (terrain, Norma, rotor sphere, FreeBOT chain), written once: as
// ros_control's loop calls read/update/write on a robot-specific object, PlantLoop owns the clock
// mode, the timeline, the actuator input, the publication period, tf, the trail, diagnostics and
// completion, and calls a PlantModel, which keeps only its model and its messages.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "spherical_robots/config/plant_loop_parameters.hpp"
#include "spherical_robots/core/periodic_schedule.hpp"
#include "spherical_robots/core/plant_checkpoint.hpp"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/plant_clock.hpp"
#include "spherical_robots/ros/plant_timeline.hpp"
#include "spherical_robots/ros/topic_rate.hpp"
#include "spherical_robots/ros/trail.hpp"

namespace spherical_robots {

/// What a plant node implements; PlantLoop calls it, always from the node's callback thread.
class PlantModel {
 public:
  struct Pose {
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
  };

  virtual ~PlantModel() = default;
  /// Takes in a measured actuator state. @throw std::invalid_argument if it cannot be trusted
  /// (the loop rejects it, keeps the last good one and reports it).
  virtual void read(const sensor_msgs::JointState& actuators) = 0;
  /// Advances the model by elapsed [s] > 0, driven by the last measured actuator state, or at rest
  /// if it is stale (actuators_fresh false). @throw on a failed step (also when it would produce
  /// a non-finite state): the loop keeps the last good state and counts the failure.
  virtual void advance(double elapsed, bool actuators_fresh) = 0;
  /// Publishes what goes out at every step, stamped now (default: nothing).
  virtual void publishEveryStep(const ros::Time& /*now*/, bool /*actuators_fresh*/) {}
  /// Publishes what goes out at publish_rate, stamped now.
  virtual void publishPeriodic(const ros::Time& now, bool actuators_fresh) = 0;
  /// The pose the trail follows; none: the plant has no trail.
  virtual std::optional<Pose> trailPose() const { return std::nullopt; }
  /// Sets the summary and adds the model's own figures (the loop adds its own after them).
  virtual void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) = 0;
  /// Where the model ended, for the "scenario complete" log line (e.g. "centre at (1, 2) m").
  virtual std::string describeState() const = 0;
  /// The model's state as numbers, which a restarted plant resumes from (~checkpoint); none:
  /// this plant keeps no checkpoint.
  virtual std::optional<std::vector<double>> checkpointState() const { return std::nullopt; }
  /// Takes up a state that checkpointState gave. @throw std::invalid_argument if it is none.
  virtual void resumeState(const std::vector<double>& /*state*/) {}
  /// The parameters of the stack's namespace its model is made of besides its private ones
  /// (they are part of the checkpoint's fingerprint).
  virtual std::vector<std::string> sharedParameters() const { return {"robot_description"}; }
};

class PlantLoop {
 public:
  /// What each plant sets: its diagnostics and its defaults of the loop's parameters.
  struct Defaults {
    std::string task;         ///< the diagnostics task, e.g. "norma plant"
    std::string hardware_id;  ///< e.g. "Norma"
    config::PlantLoopParameters parameters;  ///< step, state_timeout, trail_period, free pace
    std::size_t max_trail_points = 0;
    /// The frame the model's coordinates are in, directly under map (kMapFrame): the stack's
    /// <prefix>odom, or the FreeBOT's fixed base. The loop publishes map -> it (static, at the
    /// origin_* parameters) and the trail in it.
    std::string root_frame;
  };

  /// Reads the private parameters (pnh) with config::loadPlantLoopParameters. Nothing runs
  /// before start(). @throw std::invalid_argument on a bad parameter, naming it.
  PlantLoop(ros::NodeHandle nh, ros::NodeHandle pnh, const Defaults& defaults);

  /// A loop topic (relative to the node handle) whose publications lock-step passes on.
  template <typename Message>
  LoopPublisher advertise(const std::string& topic) {
    return step_publications_.advertise<Message>(nh_, topic);
  }
  const TfPublisher& tf() const { return tf_; }
  const std::string& rootFrame() const { return defaults_.root_frame; }
  double step() const { return parameters_.step; }
  /// [Hz] of publishPeriodic (~publish_rate).
  double publishRate() const { return parameters_.publish_rate; }
  /// Subscribes actuators/state (relative to the node handle), adds the model's diagnostics and
  /// starts the clock; `state` is the topic whose subscribers time waits for
  /// (wait_for_subscribers), published at `state_rate` [Hz] (1 / step() from publishEveryStep,
  /// publishRate() from publishPeriodic), which /diagnostics checks (topic_rate.hpp).
  void start(PlantModel& model, const LoopPublisher& state, double state_rate);

 private:
  /// Resumes the model and the timeline from the checkpoint of this run, if there is one.
  /// Returns the time to go on from (zero: a fresh start).
  ros::Time resume();
  void writeCheckpoint(const ros::Time& now);
  void onActuatorState(const ros::MessageEvent<sensor_msgs::JointState const>& event);
  std::vector<std::string> tick(const ros::Time& now);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  ros::NodeHandle nh_;
  ros::NodeHandle pnh_;
  Defaults defaults_;
  config::PlantLoopParameters parameters_;
  PlantTimeline timeline_;
  InputMonitor actuator_input_;
  StepPublications step_publications_;
  TfPublisher tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;  ///< map -> the root frame
  std::optional<Trail> trail_;
  PeriodicSchedule publication_{1.0 / parameters_.publish_rate};
  double rate_tolerance_;
  std::string state_topic_;
  std::unique_ptr<TopicRate> state_rate_;
  PlantModel* model_ = nullptr;
  std::optional<PlantCheckpointWriter> checkpoint_;  ///< none: no checkpoint
  CheckpointKey checkpoint_key_;
  unsigned long checkpoint_failures_ = 0;
  ros::Subscriber actuator_sub_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;   ///< reports on wall time (diagnostics_timer.hpp)
  std::unique_ptr<PlantClock> clock_;  ///< made last: it ticks only once everything else exists
};

}  // namespace spherical_robots
