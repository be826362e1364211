#pragma once
// The terrain_plant node: a sphere rolling over z = f(x, y), integrated from the measured
// actuator rates (terrain::stepWithHeldRates) and published as odometry, tf, state and trail.

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

#include "spherical_robots/config/odometry_parameters.hpp"
#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/ros/odometry_publisher.hpp"
#include "spherical_robots/ros/plant_loop.hpp"
#include "spherical_robots/terrain/body_frame.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots {

/// Every private parameter of terrain_plant but its loop's (PlantLoop; docs/nodes.md).
struct TerrainPlantParameters {
  terrain::RobotType robot_type = terrain::RobotType::ThreeAxisRolling;
  terrain::ContactModel contact_model = terrain::ContactModel::Paper;
  std::string frame_prefix;           ///< of every tf frame but map
  double max_actuator_rate = 1000.0;  ///< [rad/s] a measured rate beyond it is rejected
  double initial_x = 0.0;             ///< [m]
  double initial_y = 0.0;             ///< [m]
  double initial_psi = 0.0;           ///< [rad]
  double marker_half_extent = 3.0;    ///< [m] the mesh spans [-e, e]^2, a height map its extent
  double marker_resolution = 0.1;     ///< [m]
  config::OdometryParameters odometry;  ///< odom's covariances, noise; the IMU
};

/// @throw std::invalid_argument naming the parameter, its value and its limit.
TerrainPlantParameters loadTerrainPlantParameters(const config::ParameterSource& node);

/// A sphere rolling over z = f(x, y) (config/terrain.yaml, the URDF's radius), integrated from
/// the measured actuator rates (docs/nodes.md, "terrain_plant").
class TerrainPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter, URDF or terrain configuration.
  TerrainPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

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
  std::vector<std::string> sharedParameters() const override;

  terrain::DriveRates rates(bool actuators_fresh) const;
  /// base_link's exact pose and twist at the current state with these realised rates.
  BodyMotion exactMotion(const terrain::ContactGeometry& geometry, const terrain::DriveRates& realised) const;

  TerrainPlantParameters parameters_;
  std::string odom_frame_;
  std::string base_frame_;     ///< the non-rolling body at the centre (terrain::BodyFrame)
  std::string shell_frame_;
  std::string heading_frame_;  ///< R_L at the contact point
  std::unique_ptr<terrain::Surface> surface_;
  std::unique_ptr<terrain::TerrainKinematics> kinematics_;
  std::unique_ptr<terrain::BodyFrame> body_frame_;
  terrain::TerrainState state_;
  Eigen::Quaterniond orientation_;  ///< the shell's, odom <- shell
  terrain::DriveRates measured_;
  ros::Publisher marker_pub_;
  std::optional<OdometryPublisher> odometry_;  ///< made once loop_ is
  LoopPublisher joint_pub_;  ///< RS only: its tilt
  LoopPublisher state_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
