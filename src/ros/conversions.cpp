#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/core/validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots::conversions {
namespace {

constexpr double kUnitTolerance = 1e-6;
// [rad] a trolley heading is an angle the chain winds up; no run turns a trolley a million radians.
constexpr double kMaxHeading = 1e6;

void requireUnit(const Eigen::Vector3d& v, const std::string& field) {
  if (std::abs(v.norm() - 1.0) > kUnitTolerance) {
    std::ostringstream what;
    what << field << " has norm " << v.norm() << ", expected a unit vector";
    throw std::invalid_argument(what.str());
  }
}

}  // namespace

geometry_msgs::Point toPoint(const Eigen::Vector3d& p) {
  geometry_msgs::Point msg;
  msg.x = p.x();
  msg.y = p.y();
  msg.z = p.z();
  return msg;
}

geometry_msgs::Vector3 toVector3(const Eigen::Vector3d& v) {
  geometry_msgs::Vector3 msg;
  msg.x = v.x();
  msg.y = v.y();
  msg.z = v.z();
  return msg;
}

geometry_msgs::Quaternion toQuaternion(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond unit = q.normalized();
  geometry_msgs::Quaternion msg;
  msg.x = unit.x();
  msg.y = unit.y();
  msg.z = unit.z();
  msg.w = unit.w();
  return msg;
}

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

nav_msgs::Odometry toOdometry(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                              const Eigen::Vector3d& linear_velocity,
                              const Eigen::Vector3d& angular_velocity, const std::string& frame,
                              const std::string& child, const ros::Time& stamp) {
  const Eigen::Matrix3d world_from_child = orientation.normalized().toRotationMatrix();
  nav_msgs::Odometry msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.child_frame_id = child;
  msg.pose.pose.position = toPoint(position);
  msg.pose.pose.orientation = toQuaternion(orientation);
  msg.twist.twist.linear = toVector3(world_from_child.transpose() * linear_velocity);
  msg.twist.twist.angular = toVector3(world_from_child.transpose() * angular_velocity);
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
      throw std::invalid_argument("JointState lacks actuator '" + name + "'");
    const double value = values[found - msg.name.begin()];
    requireMagnitudeAtMost(value, max_magnitude, what + " of actuator '" + name + "'");
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

sensor_msgs::JointState velocityJointState(const std::vector<std::string>& names,
                                           const std::vector<double>& velocities,
                                           const ros::Time& stamp) {
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  msg.name = names;
  msg.velocity = velocities;
  return msg;
}

terrain::DriveRates ratesFromJointState(terrain::RobotType type, const sensor_msgs::JointState& msg,
                                        double max_rate) {
  try {
    return terrain::ratesFromActuated(
        type, velocitiesByName(msg, terrain::actuatorNames(type), max_rate));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()) + " (robot type " +
                                terrain::toString(type) + ")");
  }
}

sensor_msgs::JointState jointStateFromRates(terrain::RobotType type, const terrain::DriveRates& rates,
                                            const ros::Time& stamp) {
  return velocityJointState(terrain::actuatorNames(type), terrain::actuatedValues(type, rates),
                            stamp);
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

spherical_robots::TerrainState toTerrainStateMsg(terrain::RobotType type, terrain::ContactModel model,
                                                 const terrain::TerrainState& state,
                                                 const terrain::ContactGeometry& geometry,
                                                 const terrain::DriveRates& realised,
                                                 const ros::Time& stamp) {
  spherical_robots::TerrainState msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = kWorldFrame;
  msg.robot_type = terrain::toString(type);
  msg.contact_model = terrain::toString(model);
  msg.contact_point = toPoint(geometry.contact_point);
  msg.centre = toPoint(geometry.centre);
  msg.normal = toVector3(geometry.heading_frame.col(2));
  msg.heading = toVector3(geometry.heading_frame.col(0));
  msg.psi = state.psi;
  msg.phi = state.phi;
  msg.roll_rate = realised.roll_rate;
  msg.lateral_rate = realised.lateral_rate;
  msg.turn_rate = realised.turn_rate;
  return msg;
}

terrain::ContactGeometry contactGeometryFromMsg(const spherical_robots::TerrainState& msg,
                                                double max_position) {
  const Eigen::Vector3d normal = fromVector3(msg.normal, "normal");
  const Eigen::Vector3d heading = fromVector3(msg.heading, "heading");
  requireUnit(normal, "normal");
  requireUnit(heading, "heading");
  if (std::abs(normal.dot(heading)) > kUnitTolerance) {
    std::ostringstream what;
    what << "heading is not perpendicular to normal (h.n = " << normal.dot(heading) << ")";
    throw std::invalid_argument(what.str());
  }
  if (!(normal.z() > 0.0)) {
    std::ostringstream what;
    what << "normal.z = " << normal.z() << " does not point up";
    throw std::invalid_argument(what.str());
  }
  return terrain::contactGeometryFromAxes(
      boundedPoint(msg.contact_point, "contact_point", max_position),
      boundedPoint(msg.centre, "centre", max_position), normal, heading);
}

spherical_robots::TrackingError toTrackingErrorMsg(const terrain::TrackingError& error,
                                                   const terrain::DesiredPoint& desired,
                                                   const std::string& frame, const ros::Time& stamp) {
  spherical_robots::TrackingError msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.desired = toPoint(desired.position);
  msg.desired_velocity = toVector3(desired.velocity);
  msg.error = toVector3(error.error);
  msg.error_norm = error.norm;
  msg.zeta = error.zeta;
  return msg;
}

nav_msgs::Path sampledPath(const terrain::ReferencePath& path, const terrain::Surface& surface,
                           int samples, const std::string& frame, const ros::Time& stamp) {
  if (samples < 2) {
    throw std::invalid_argument("sampledPath: samples = " + std::to_string(samples) + " < 2");
  }
  nav_msgs::Path msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  const double period = path.period();
  for (int i = 0; i < samples; ++i) {
    const double t = period * i / (samples - 1);
    const terrain::DesiredPoint point = terrain::liftOntoSurface(path, surface, t);
    msg.poses.push_back(toPoseStamped(point.position, Eigen::Quaterniond::Identity(), frame, stamp));
  }
  return msg;
}

visualization_msgs::Marker surfaceMesh(const terrain::Surface& surface, double half_extent,
                                       double resolution, const std::string& frame,
                                       const ros::Time& stamp) {
  constexpr double kMaxCells = 1000.0;
  if (!(half_extent > 0.0) || !(resolution > 0.0) || !std::isfinite(half_extent) ||
      !std::isfinite(resolution) || 2.0 * half_extent / resolution > kMaxCells) {
    std::ostringstream what;
    what << "surfaceMesh: half_extent = " << half_extent << " m and resolution = " << resolution
         << " m must be positive, finite and give at most " << kMaxCells << " cells a side";
    throw std::invalid_argument(what.str());
  }
  const int cells = static_cast<int>(std::ceil(2.0 * half_extent / resolution));
  const double spacing = 2.0 * half_extent / cells;
  Eigen::MatrixXd height(cells + 1, cells + 1);
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      height(i, j) = surface.height(-half_extent + i * spacing, -half_extent + j * spacing);
    }
  }
  const double low = height.minCoeff();
  const double span = std::max(height.maxCoeff() - low, 1e-9);

  visualization_msgs::Marker msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.ns = "terrain";
  msg.id = 0;
  msg.type = visualization_msgs::Marker::TRIANGLE_LIST;
  msg.action = visualization_msgs::Marker::ADD;
  msg.pose.orientation.w = 1.0;
  msg.scale.x = msg.scale.y = msg.scale.z = 1.0;
  msg.color.r = msg.color.g = msg.color.b = msg.color.a = 1.0;
  auto vertex = [&](int i, int j) {
    msg.points.push_back(toPoint(
        {-half_extent + i * spacing, -half_extent + j * spacing, height(i, j)}));
    const double level = (height(i, j) - low) / span;  // 0 in the valleys, 1 on the ridges
    std_msgs::ColorRGBA colour;
    colour.r = static_cast<float>(0.25 + 0.5 * level);
    colour.g = static_cast<float>(0.45 + 0.3 * level);
    colour.b = static_cast<float>(0.25 + 0.1 * level);
    colour.a = 1.0f;
    msg.colors.push_back(colour);
  };
  // Two counter-clockwise (seen from above) triangles per cell.
  constexpr std::array<std::pair<int, int>, 6> kCellTriangles{
      {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}};
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      for (const auto& [di, dj] : kCellTriangles) vertex(i + di, j + dj);
    }
  }
  return msg;
}

// --- FreeBOT -----------------------------------------------------------------------------------

Eigen::Quaterniond fromQuaternion(const geometry_msgs::Quaternion& q, const std::string& field,
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
  return value.normalized();
}

std::vector<std::string> freebotWheelNames(std::size_t modules) {
  std::vector<std::string> names;
  for (std::size_t i = 1; i <= modules; ++i) {
    names.push_back("module" + std::to_string(i) + "_wheel_right");
    names.push_back("module" + std::to_string(i) + "_wheel_left");
  }
  return names;
}

std::vector<freebot::WheelSpeeds> wheelSpeedsFromJointState(const sensor_msgs::JointState& msg,
                                                            std::size_t modules, double max_rate) {
  const std::vector<double> values = velocitiesByName(msg, freebotWheelNames(modules), max_rate);
  std::vector<freebot::WheelSpeeds> wheels(modules);
  for (std::size_t i = 0; i < modules; ++i) wheels[i] = {values[2 * i], values[2 * i + 1]};
  return wheels;
}

sensor_msgs::JointState jointStateFromWheelSpeeds(const std::vector<freebot::WheelSpeeds>& wheels,
                                                  const ros::Time& stamp) {
  std::vector<double> values;
  for (const freebot::WheelSpeeds& pair : wheels) {
    values.push_back(pair.right);
    values.push_back(pair.left);
  }
  return velocityJointState(freebotWheelNames(wheels.size()), values, stamp);
}

spherical_robots::FreebotState toFreebotStateMsg(const freebot::ChainState& state,
                                                 const freebot::LinkPose& end,
                                                 const std::string& frame, const ros::Time& stamp) {
  spherical_robots::FreebotState msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  for (const freebot::SrcJointState& joint : state.joints) {
    msg.link.push_back(toQuaternion(joint.link));
    msg.base.push_back(toQuaternion(joint.base));
  }
  msg.heading = state.headings;
  msg.end_effector.position = toPoint(end.position);
  msg.end_effector.orientation = toQuaternion(end.orientation);
  return msg;
}

freebot::ChainState chainStateFromMsg(const spherical_robots::FreebotState& msg) {
  if (msg.link.size() != msg.base.size() || msg.link.size() != msg.heading.size()) {
    throw std::invalid_argument("link, base and heading must have one entry per joint, got " +
                                std::to_string(msg.link.size()) + ", " +
                                std::to_string(msg.base.size()) + ", " +
                                std::to_string(msg.heading.size()));
  }
  freebot::ChainState state;
  for (std::size_t i = 0; i < msg.link.size(); ++i) {
    const std::string joint = "[" + std::to_string(i) + "]";
    state.joints.push_back({fromQuaternion(msg.link[i], "link" + joint),
                            fromQuaternion(msg.base[i], "base" + joint)});
    requireMagnitudeAtMost(msg.heading[i], kMaxHeading, "heading" + joint + " [rad]");
    state.headings.push_back(msg.heading[i]);
  }
  return state;
}

spherical_robots::FreebotGoalResult toGoalResultMsg(const freebot::GoalVerdict& verdict,
                                                    const geometry_msgs::Pose& goal,
                                                    const std::string& frame,
                                                    const ros::Time& stamp) {
  using Result = spherical_robots::FreebotGoalResult;
  using freebot::GoalStatus;
  static_assert(static_cast<int>(GoalStatus::Moving) == Result::MOVING &&
                    static_cast<int>(GoalStatus::Arrived) == Result::ARRIVED &&
                    static_cast<int>(GoalStatus::Unreachable) == Result::UNREACHABLE &&
                    static_cast<int>(GoalStatus::Rejected) == Result::REJECTED &&
                    static_cast<int>(GoalStatus::Preempted) == Result::PREEMPTED &&
                    static_cast<int>(GoalStatus::Aborted) == Result::ABORTED,
                "freebot::GoalStatus must list msg/FreebotGoalResult.msg's statuses in order");
  Result result;
  result.header.stamp = stamp;
  result.header.frame_id = frame;
  result.status = static_cast<std::uint8_t>(verdict.status);
  const Eigen::Vector4d orientation(goal.orientation.x, goal.orientation.y, goal.orientation.z,
                                    goal.orientation.w);
  if (Eigen::Vector3d(goal.position.x, goal.position.y, goal.position.z).allFinite() &&
      orientation.allFinite())
    result.goal = goal;
  result.position_error = verdict.position_error;
  result.orientation_error = verdict.orientation_error;
  result.elapsed = verdict.elapsed;
  result.message = verdict.message;
  return result;
}

}  // namespace spherical_robots::conversions
