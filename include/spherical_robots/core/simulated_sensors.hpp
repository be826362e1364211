#pragma once
// A simulated plant's odometry and IMU, from its exact motion: seeded Gaussian noise (off by
// default) so that a loop can be closed through imperfect sensing, and the IMU's specific force
// (REP 145: gravity included, +9.81 m/s^2 up at rest). No ROS: the plants' nodes publish what this
// returns (docs/nodes.md, "Odometry and IMU").

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <random>

namespace spherical_robots {

/// A body's pose in its odometry frame and its twist in its own axes.
struct BodyMotion {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();                ///< [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< odom <- body, unit
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();                  ///< [m/s], body axes
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();                 ///< [rad/s], body axes
};

/// The motion with the velocities given in the odometry frame's axes, turned into the body's.
BodyMotion bodyMotion(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                      const Eigen::Vector3d& linear_velocity, const Eigen::Vector3d& angular_velocity);

/// Standard deviations of the noise, each >= 0 (0: that part exact); a seed makes runs repeatable.
struct SensorNoise {
  double position = 0.0;             ///< [m] odometry, each axis
  double yaw = 0.0;                  ///< [rad] odometry and IMU orientation, a turn about z
  double linear_velocity = 0.0;      ///< [m/s] odometry twist, each axis
  double angular_velocity = 0.0;     ///< [rad/s] odometry twist and IMU, each axis
  double linear_acceleration = 0.0;  ///< [m/s^2] IMU, each axis
  std::uint32_t seed = 0;
};

/// What an IMU in the body reads, in the body's axes.
struct ImuReading {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< odom <- body
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();       ///< [rad/s]
  Eigen::Vector3d linear_acceleration = Eigen::Vector3d::Zero();    ///< specific force [m/s^2]
};

class SimulatedSensors {
 public:
  static constexpr double kGravity = 9.81;  ///< [m/s^2], along -z of the odometry frame

  /// @throw std::invalid_argument naming the first standard deviation that is not finite and >= 0.
  explicit SimulatedSensors(const SensorNoise& noise);

  /// The odometry of `truth`: independent draws added to each position and twist component and a
  /// turn about z by the yaw draw; exactly `truth` where the deviation is 0.
  BodyMotion odometry(const BodyMotion& truth);

  /// The IMU at time t [s]: the orientation (turned by a yaw draw), the angular velocity and the
  /// specific force R^T (a + g z), a the centre's acceleration by the backward difference of its
  /// velocity since the previous reading (0 at the first, and after t went back), each component
  /// plus its draw.
  ImuReading imu(double t, const BodyMotion& truth);

  const SensorNoise& noise() const { return noise_; }

 private:
  /// A seeded stream of standard normal draws.
  struct Stream {
    std::mt19937 engine;
    std::normal_distribution<double> normal;
    /// `sigma` times a draw, or exactly 0 (no draw) if sigma is 0.
    double draw(double sigma);
    Eigen::Vector3d draw3(double sigma);
  };
  Eigen::Quaterniond turned(Stream& stream, const Eigen::Quaterniond& orientation);

  SensorNoise noise_;
  // One stream each, so that turning the IMU on or off leaves the odometry's draws as they were.
  Stream odometry_stream_;
  Stream imu_stream_;
  std::optional<std::pair<double, Eigen::Vector3d>> last_velocity_;  ///< (t, odom-axes velocity)
};

}  // namespace spherical_robots
