#include "spherical_robots/core/simulated_sensors.hpp"

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots {

BodyMotion bodyMotion(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                      const Eigen::Vector3d& linear_velocity, const Eigen::Vector3d& angular_velocity) {
  const Eigen::Matrix3d body_from_odom = orientation.toRotationMatrix().transpose();
  return {position, orientation, body_from_odom * linear_velocity, body_from_odom * angular_velocity};
}

namespace {

std::mt19937 engineFor(std::uint32_t seed, std::uint32_t stream) {
  std::seed_seq sequence{seed, stream};
  return std::mt19937(sequence);
}

}  // namespace

SimulatedSensors::SimulatedSensors(const SensorNoise& noise)
    : noise_(noise),
      odometry_stream_{engineFor(noise.seed, 0), {}},
      imu_stream_{engineFor(noise.seed, 1), {}} {
  for (const auto& [sigma, what] :
       {std::pair{noise.position, "position noise [m]"}, {noise.yaw, "yaw noise [rad]"},
        {noise.linear_velocity, "linear velocity noise [m/s]"},
        {noise.angular_velocity, "angular velocity noise [rad/s]"},
        {noise.linear_acceleration, "linear acceleration noise [m/s^2]"}}) {
    requireFinite(sigma, what);
    requireNonNegative(sigma, what);
  }
}

double SimulatedSensors::Stream::draw(double sigma) {
  return sigma == 0.0 ? 0.0 : sigma * normal(engine);
}

Eigen::Vector3d SimulatedSensors::Stream::draw3(double sigma) {
  const double x = draw(sigma), y = draw(sigma), z = draw(sigma);
  return {x, y, z};
}

Eigen::Quaterniond SimulatedSensors::turned(Stream& stream, const Eigen::Quaterniond& orientation) {
  if (noise_.yaw == 0.0) return orientation;
  return Eigen::Quaterniond(Eigen::AngleAxisd(stream.draw(noise_.yaw), Eigen::Vector3d::UnitZ())) *
         orientation;
}

BodyMotion SimulatedSensors::odometry(const BodyMotion& truth) {
  BodyMotion measured = truth;
  // Adding an exact 0 would still turn a -0.0 into +0.0: only where there is noise.
  if (noise_.position != 0.0) measured.position += odometry_stream_.draw3(noise_.position);
  measured.orientation = turned(odometry_stream_, truth.orientation);
  if (noise_.linear_velocity != 0.0) measured.linear += odometry_stream_.draw3(noise_.linear_velocity);
  if (noise_.angular_velocity != 0.0)
    measured.angular += odometry_stream_.draw3(noise_.angular_velocity);
  return measured;
}

ImuReading SimulatedSensors::imu(double t, const BodyMotion& truth) {
  const Eigen::Vector3d velocity = truth.orientation * truth.linear;  // odometry axes
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  if (last_velocity_ && t > last_velocity_->first)
    acceleration = (velocity - last_velocity_->second) / (t - last_velocity_->first);
  last_velocity_ = {t, velocity};
  ImuReading reading;
  reading.orientation = turned(imu_stream_, truth.orientation);
  reading.angular_velocity = truth.angular + imu_stream_.draw3(noise_.angular_velocity);
  reading.linear_acceleration =
      truth.orientation.conjugate() * (acceleration + kGravity * Eigen::Vector3d::UnitZ()) +
      imu_stream_.draw3(noise_.linear_acceleration);
  return reading;
}

}  // namespace spherical_robots
