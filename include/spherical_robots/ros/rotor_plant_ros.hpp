#pragma once
// The rotor_plant node: the two-rotor sphere (Svinin et al.) rolled from the measured rotor
// speeds of the hardware interface (eq 11 solved for ω, eqs 6-10; rotor::advancePlant), published
// as odometry, tf and the rotors' joint states.

#include <array>
#include <optional>
#include <string>

#include "spherical_robots/config/odometry_parameters.hpp"
#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/ros/odometry_publisher.hpp"
#include "spherical_robots/ros/plant_loop.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"

namespace spherical_robots {

/// Every parameter of rotor_plant but its loop's (PlantLoop; docs/nodes.md).
struct RotorPlantParameters {
  double inertia_ratio = 2.5;          ///< k, the stack's (shared with rotor_planner)
  double rotor_inertia_scale = 12.0;   ///< J_zz / J_r, the stack's
  double sphere_radius = 0.1;          ///< R [m]
  std::string frame_prefix;            ///< of every tf frame but map
  double max_actuator_rate = 1000.0;   ///< [rad/s] a measured rate beyond it is rejected
  config::OdometryParameters odometry;  ///< odom's covariances, noise; the IMU
};

/// stack: the stack's namespace (inertia_ratio, rotor_inertia_scale); node: the private one.
/// @throw std::invalid_argument naming the parameter, its value and its limit.
RotorPlantParameters loadRotorPlantParameters(const config::ParameterSource& stack,
                                              const config::ParameterSource& node);

/// The two-rotor sphere rolled from the measured rotor speeds, starting at the zero state
/// (contact at the south pole, at the origin, psi = 0) (docs/nodes.md, "rotor_plant").
class RotorPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  RotorPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void read(const sensor_msgs::JointState& actuators) override;
  void advance(double elapsed, bool actuators_fresh) override;
  void publishPeriodic(const ros::Time& now, bool actuators_fresh) override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  std::string describeState() const override;

  RotorPlantParameters parameters_;
  std::string odom_frame_;
  std::string base_frame_;  ///< the shell itself: the sphere has no non-rolling body
  rotor::ContactCoordinates state_;
  rotor::RotorSpeeds speeds_;  ///< measured [rad/s]
  std::array<double, 2> positions_{};  ///< measured rotor angles [rad], for the URDF joints
  std::optional<OdometryPublisher> odometry_;  ///< made once loop_ is
  LoopPublisher joint_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
