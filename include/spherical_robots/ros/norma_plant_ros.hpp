#pragma once
// The norma_plant plant node: Norma (eq 46, eqs 6 and 12) integrated from the measured
// pendulum torque and slider force of the hardware interface, published as its state, odometry,
// joint states and tf.

#include <optional>
#include <string>

#include "spherical_robots/config/odometry_parameters.hpp"
#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/norma/norma_plant.hpp"
#include "spherical_robots/ros/odometry_publisher.hpp"
#include "spherical_robots/ros/plant_loop.hpp"

namespace spherical_robots {

/// Every private parameter of norma_plant but its loop's (PlantLoop; docs/nodes.md).
struct NormaPlantParameters {
  norma::LagrangianVariant variant = norma::LagrangianVariant::kText;  ///< docs/errata.md
  std::string frame_prefix;             ///< of every tf frame but map
  double max_actuator_effort = 1e4;     ///< [N m or N] a measured effort beyond it is rejected
  double initial_psi = 0.0;             ///< [rad] the initial heading
  config::OdometryParameters odometry;  ///< odom's covariances, noise; the IMU
};

/// @throw std::invalid_argument naming the parameter, its value and its limit.
NormaPlantParameters loadNormaPlantParameters(const config::ParameterSource& node);

/// Norma (robot_description: urdf/norma.urdf) integrated from the measured pendulum torque and
/// slider force (docs/nodes.md, "norma_plant").
class NormaPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter or URDF.
  NormaPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void read(const sensor_msgs::JointState& actuators) override;
  void advance(double elapsed, bool actuators_fresh) override;
  void publishEveryStep(const ros::Time& now, bool actuators_fresh) override;
  void publishPeriodic(const ros::Time& now, bool actuators_fresh) override;
  std::optional<Pose> trailPose() const override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  std::string describeState() const override;
  std::optional<std::vector<double>> checkpointState() const override;
  void resumeState(const std::vector<double>& state) override;
  /// The sphere's centre in odom [m].
  Eigen::Vector3d centre() const;

  NormaPlantParameters parameters_;
  norma::NormaDynamics dynamics_;
  std::string odom_frame_;
  std::string base_frame_;
  norma::NormaState state_;
  norma::Efforts measured_;  ///< the last good actuator state's efforts
  LoopPublisher state_pub_;
  std::optional<OdometryPublisher> odometry_;  ///< made once loop_ is
  LoopPublisher joint_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
