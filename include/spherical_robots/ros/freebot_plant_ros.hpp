#pragma once
// The freebot_plant node: a FreeBOT chain integrated from the MEASURED wheel speeds (core
// FreebotChain::advance) and published as its state, tf and markers: with a real driver, the
// chain's dead-reckoning estimate (docs/nodes.md, "freebot_plant").

#include <optional>
#include <string>
#include <vector>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/freebot/freebot_chain.hpp"
#include "spherical_robots/ros/plant_loop.hpp"

namespace spherical_robots {

/// Every parameter of freebot_plant but its loop's (PlantLoop; docs/nodes.md).
struct FreebotPlantParameters {
  freebot::FreebotChain chain;        ///< freebot/radii, freebot/trolley/*
  std::string frame_prefix;           ///< of every tf frame but map
  double max_actuator_rate = 1000.0;  ///< [rad/s] a measured rate beyond it is rejected
};

/// stack: the stack's namespace (config/freebot.yaml); node: the private one.
/// @throw std::invalid_argument naming the parameter on a missing or bad one.
FreebotPlantParameters loadFreebotPlantParameters(const config::ParameterSource& stack,
                                                  const config::ParameterSource& node);

class FreebotPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  FreebotPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void read(const sensor_msgs::JointState& actuators) override;
  void advance(double elapsed, bool actuators_fresh) override;
  void publishEveryStep(const ros::Time& now, bool actuators_fresh) override;
  /// tf of every module's sphere and the markers.
  void publishPeriodic(const ros::Time& now, bool actuators_fresh) override;
  std::optional<Pose> trailPose() const override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  std::string describeState() const override;
  const freebot::FreebotChain& chain() const { return parameters_.chain; }

  FreebotPlantParameters parameters_;
  freebot::ChainState state_;
  std::vector<freebot::WheelSpeeds> wheels_;  ///< last measured [rad/s]
  LoopPublisher state_pub_;
  LoopPublisher marker_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
