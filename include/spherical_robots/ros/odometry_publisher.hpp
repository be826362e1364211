#pragma once
// A simulated plant's odometry (nav_msgs/Odometry on odom) and IMU (sensor_msgs/Imu on imu, with
// ~imu_rate > 0), from its exact motion through core SimulatedSensors: the noise and the IMU of
// every plant, written once (docs/nodes.md, "Odometry and IMU").

#include <ros/time.h>

#include <optional>
#include <string>

#include "spherical_robots/config/odometry_parameters.hpp"
#include "spherical_robots/core/periodic_schedule.hpp"
#include "spherical_robots/core/simulated_sensors.hpp"
#include "spherical_robots/ros/plant_loop.hpp"

namespace spherical_robots {

class OdometryPublisher {
 public:
  /// Advertises odom, and imu if parameters.imu_rate > 0, as loop topics of `loop`.
  /// @throw std::invalid_argument on a bad noise deviation.
  OdometryPublisher(PlantLoop& loop, const config::OdometryParameters& parameters,
                    std::string odom_frame, std::string base_frame);

  /// odom of `truth` (pose in the odom frame, twist in the base frame), stamped now.
  void publish(const ros::Time& now, const BodyMotion& truth);

  /// Whether an IMU reading is due at now (never with ~imu_rate 0), which counts it as taken: the
  /// plant then calls publishImu, at most once a step.
  bool imuDue(const ros::Time& now);
  /// The IMU of `truth` (in the base frame), stamped now.
  void publishImu(const ros::Time& now, const BodyMotion& truth);

  /// The odom publication, whose subscribers simulated time waits for (PlantLoop::start).
  const LoopPublisher& odom() const { return odom_pub_; }

 private:
  config::OdometryParameters parameters_;
  std::string odom_frame_;
  std::string base_frame_;
  SimulatedSensors sensors_;
  LoopPublisher odom_pub_;
  LoopPublisher imu_pub_;
  std::optional<PeriodicSchedule> imu_schedule_;  ///< with ~imu_rate > 0
};

}  // namespace spherical_robots
