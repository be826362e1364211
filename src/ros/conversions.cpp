#include "spherical_robots/ros/conversions.hpp"

#include <tf2_eigen/tf2_eigen.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::conversions {

geometry_msgs::Point toPoint(const Eigen::Vector3d& p) { return tf2::toMsg(p); }

geometry_msgs::Vector3 toVector3(const Eigen::Vector3d& v) {
  geometry_msgs::Vector3 msg;
  return tf2::toMsg(v, msg);
}

geometry_msgs::Quaternion toQuaternion(const Eigen::Quaterniond& q) { return tf2::toMsg(q.normalized()); }

namespace {

/// (x, y, z), each finite and, unless max_magnitude is infinite, of magnitude <= max_magnitude.
/// @throw std::invalid_argument naming `field`.x, .y or .z.
Eigen::Vector3d checkedXyz(double x, double y, double z, const std::string& field,
                           double max_magnitude) {
  const double values[3] = {x, y, z};
  const char* const axes[3] = {".x", ".y", ".z"};
  for (int i = 0; i < 3; ++i) {
    if (std::isinf(max_magnitude))
      requireFinite(values[i], field + axes[i]);
    else
      requireMagnitudeAtMost(values[i], max_magnitude, field + axes[i]);
  }
  return {x, y, z};
}

constexpr double kAnyFinite = std::numeric_limits<double>::infinity();

}  // namespace

Eigen::Vector3d fromPoint(const geometry_msgs::Point& p, const std::string& field) {
  return checkedXyz(p.x, p.y, p.z, field, kAnyFinite);
}

Eigen::Vector3d boundedPoint(const geometry_msgs::Point& p, const std::string& field,
                             double max_magnitude) {
  return checkedXyz(p.x, p.y, p.z, field, max_magnitude);
}

Eigen::Vector3d boundedVector3(const geometry_msgs::Vector3& v, const std::string& field,
                               double max_magnitude) {
  return checkedXyz(v.x, v.y, v.z, field, max_magnitude);
}

Eigen::Vector3d fromVector3(const geometry_msgs::Vector3& v, const std::string& field) {
  return checkedXyz(v.x, v.y, v.z, field, kAnyFinite);
}

geometry_msgs::TransformStamped toTransform(const Eigen::Vector3d& translation,
                                            const Eigen::Quaterniond& rotation,
                                            const std::string& parent, const std::string& child,
                                            const ros::Time& stamp) {
  geometry_msgs::TransformStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = parent;
  msg.child_frame_id = child;
  msg.transform.translation = toVector3(translation);
  msg.transform.rotation = toQuaternion(rotation);
  return msg;
}

geometry_msgs::PoseStamped toPoseStamped(const Eigen::Vector3d& position,
                                         const Eigen::Quaterniond& orientation,
                                         const std::string& frame, const ros::Time& stamp) {
  geometry_msgs::PoseStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.pose.position = toPoint(position);
  msg.pose.orientation = toQuaternion(orientation);
  return msg;
}

nav_msgs::Odometry bodyOdometry(const BodyMotion& motion, const config::OdometryParameters& odometry,
                                const std::string& frame, const std::string& child,
                                const ros::Time& stamp) {
  nav_msgs::Odometry msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.child_frame_id = child;
  msg.pose.pose.position = toPoint(motion.position);
  msg.pose.pose.orientation.x = motion.orientation.x();
  msg.pose.pose.orientation.y = motion.orientation.y();
  msg.pose.pose.orientation.z = motion.orientation.z();
  msg.pose.pose.orientation.w = motion.orientation.w();
  msg.twist.twist.linear = toVector3(motion.linear);
  msg.twist.twist.angular = toVector3(motion.angular);
  for (int i = 0; i < 6; ++i) {  // row-major 6 x 6
    msg.pose.covariance[7 * i] = odometry.pose_covariance_diagonal[i];
    msg.twist.covariance[7 * i] = odometry.twist_covariance_diagonal[i];
  }
  return msg;
}

sensor_msgs::Imu toImu(const ImuReading& reading, const config::OdometryParameters& odometry,
                       const std::string& frame, const ros::Time& stamp) {
  sensor_msgs::Imu msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.orientation = toQuaternion(reading.orientation);
  msg.angular_velocity = toVector3(reading.angular_velocity);
  msg.linear_acceleration = toVector3(reading.linear_acceleration);
  for (int i = 0; i < 3; ++i) {  // row-major 3 x 3
    msg.orientation_covariance[4 * i] = odometry.imu_orientation_covariance_diagonal[i];
    msg.angular_velocity_covariance[4 * i] = odometry.imu_angular_velocity_covariance_diagonal[i];
    msg.linear_acceleration_covariance[4 * i] =
        odometry.imu_linear_acceleration_covariance_diagonal[i];
  }
  return msg;
}

namespace {

/// values[k] of each named actuator (values: msg.velocity or msg.effort, called `what`).
std::vector<double> valuesByName(const sensor_msgs::JointState& msg, const std::vector<double>& values,
                                 const std::string& what, const std::vector<std::string>& names,
                                 double max_magnitude) {
  if (values.size() < msg.name.size()) {
    std::ostringstream problem;
    problem << "JointState has " << msg.name.size() << " names but " << values.size() << " "
            << what << " values";
    throw std::invalid_argument(problem.str());
  }
  std::vector<double> found_values;
  for (const std::string& name : names) {
    const auto found = std::find(msg.name.begin(), msg.name.end(), name);
    if (found == msg.name.end())
      throw std::invalid_argument("JointState lacks '" + name + "'");
    const double value = values[found - msg.name.begin()];
    requireMagnitudeAtMost(value, max_magnitude, what + " of '" + name + "'");
    found_values.push_back(value);
  }
  return found_values;
}

}  // namespace

std::vector<double> velocitiesByName(const sensor_msgs::JointState& msg,
                                     const std::vector<std::string>& names, double max_rate) {
  return valuesByName(msg, msg.velocity, "velocity", names, max_rate);
}

std::vector<double> effortsByName(const sensor_msgs::JointState& msg,
                                  const std::vector<std::string>& names, double max_effort) {
  return valuesByName(msg, msg.effort, "effort", names, max_effort);
}

std::vector<double> positionsByName(const sensor_msgs::JointState& msg,
                                    const std::vector<std::string>& names, double max_position) {
  return valuesByName(msg, msg.position, "position", names, max_position);
}

sensor_msgs::JointState velocityJointState(const std::vector<std::string>& names,
                                           const std::vector<double>& velocities,
                                           const ros::Time& stamp) {
  return jointState(names, {}, velocities, {}, stamp);
}

PlanarTwist planarTwist(const geometry_msgs::Twist& twist, double max_magnitude) {
  const Eigen::Vector3d linear = boundedVector3(twist.linear, "linear", max_magnitude);
  const Eigen::Vector3d angular = boundedVector3(twist.angular, "angular", max_magnitude);
  PlanarTwist result;
  result.request = {linear.x(), linear.y(), angular.z()};
  if (linear.z() != 0.0) result.ignored.emplace_back("linear.z");
  if (angular.x() != 0.0) result.ignored.emplace_back("angular.x");
  if (angular.y() != 0.0) result.ignored.emplace_back("angular.y");
  return result;
}

Eigen::Isometry3d fromTransform(const geometry_msgs::Transform& transform, const std::string& field) {
  Eigen::Isometry3d isometry = Eigen::Isometry3d::Identity();
  isometry.translation() = fromVector3(transform.translation, field + ".translation");
  isometry.linear() = fromQuaternion(transform.rotation, field + ".rotation").toRotationMatrix();
  return isometry;
}

Eigen::Quaterniond checkedQuaternion(const geometry_msgs::Quaternion& q, const std::string& field,
                                     double tolerance) {
  const Eigen::Quaterniond value(q.w, q.x, q.y, q.z);
  if (!value.coeffs().allFinite())
    throw std::invalid_argument(field + " has a non-finite coefficient");
  if (std::abs(value.norm() - 1.0) > tolerance) {
    std::ostringstream what;
    what << field << " has norm " << value.norm() << ", expected a unit quaternion (within "
         << tolerance << ")";
    throw std::invalid_argument(what.str());
  }
  return value;
}

Eigen::Quaterniond fromQuaternion(const geometry_msgs::Quaternion& q, const std::string& field,
                                  double tolerance) {
  return checkedQuaternion(q, field, tolerance).normalized();
}

geometry_msgs::PointStamped toPointStamped(const Eigen::Vector3d& p, const std::string& frame,
                                           const ros::Time& stamp) {
  geometry_msgs::PointStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.point = toPoint(p);
  return msg;
}

sensor_msgs::JointState jointState(const std::vector<std::string>& names,
                                   const std::vector<double>& positions,
                                   const std::vector<double>& velocities,
                                   const std::vector<double>& efforts, const ros::Time& stamp) {
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  msg.name = names;
  msg.position = positions;
  msg.velocity = velocities;
  msg.effort = efforts;
  return msg;
}

visualization_msgs::Marker marker(const std::string& ns, int id, int type, const std::string& frame,
                                  const ros::Time& stamp) {
  visualization_msgs::Marker msg;
  msg.header.frame_id = frame;
  msg.header.stamp = stamp;
  msg.ns = ns;
  msg.id = id;
  msg.type = type;
  msg.action = visualization_msgs::Marker::ADD;
  msg.pose.orientation.w = 1.0;
  msg.color.a = 1.0;
  return msg;
}

}  // namespace spherical_robots::conversions
