#include "spherical_robots/ros/terrain_conversions.hpp"
#include "spherical_robots/core/validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots::conversions {

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

spherical_robots::TerrainState toTerrainStateMsg(terrain::RobotType type, terrain::ContactModel model,
                                                 const terrain::TerrainState& state,
                                                 const terrain::ContactGeometry& geometry,
                                                 const terrain::DriveRates& realised,
                                                 const std::string& frame, const ros::Time& stamp) {
  spherical_robots::TerrainState msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
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

terrain::BodyPose bodyPoseFromOdometry(const nav_msgs::Odometry& msg, double max_position) {
  return {boundedPoint(msg.pose.pose.position, "pose.position", max_position),
          checkedQuaternion(msg.pose.pose.orientation, "pose.orientation")};
}

sensor_msgs::JointState tiltJointState(double phi, double phi_rate, const ros::Time& stamp) {
  return jointState({kTiltJoint}, {phi}, {phi_rate}, {}, stamp);
}

double tiltFromJointState(const sensor_msgs::JointState& msg) {
  const auto found = std::find(msg.name.begin(), msg.name.end(), kTiltJoint);
  if (found == msg.name.end()) throw std::invalid_argument("joint_states lacks joint '" + kTiltJoint + "'");
  const std::size_t index = found - msg.name.begin();
  if (index >= msg.position.size())
    throw std::invalid_argument("joint_states has no position for joint '" + kTiltJoint + "'");
  const double phi = msg.position[index];
  requireMagnitudeAtMost(phi, M_PI / 2.0, "position of joint '" + kTiltJoint + "' [rad]");
  return phi;
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

std::vector<terrain::StampedPoint> stampedPointsFromPath(const nav_msgs::Path& msg,
                                                         const Eigen::Isometry3d& to_fixed,
                                                         double max_position) {
  std::vector<terrain::StampedPoint> points;
  points.reserve(msg.poses.size());
  for (std::size_t i = 0; i < msg.poses.size(); ++i) {
    const geometry_msgs::PoseStamped& pose = msg.poses[i];
    const std::string field = "poses[" + std::to_string(i) + "]";
    if (!pose.header.frame_id.empty() && pose.header.frame_id != msg.header.frame_id) {
      throw std::invalid_argument(field + " is in frame '" + pose.header.frame_id +
                                  "', the path in '" + msg.header.frame_id + "'");
    }
    const Eigen::Vector3d position =
        to_fixed * boundedPoint(pose.pose.position, field + ".pose.position", max_position);
    points.push_back({nanosecondsOf(pose.header.stamp), position.head<2>()});
  }
  return points;
}

nav_msgs::Path sampledPath(const terrain::ReferencePath& path, const terrain::Surface& surface,
                           int samples, const std::string& frame, const ros::Time& stamp) {
  if (samples < 2) {
    throw std::invalid_argument("sampledPath: samples = " + std::to_string(samples) + " < 2");
  }
  nav_msgs::Path msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  const double duration = path.duration();
  for (int i = 0; i < samples; ++i) {
    const double t = duration * i / (samples - 1);
    const terrain::DesiredPoint point = terrain::liftOntoSurface(path, surface, t);
    msg.poses.push_back(toPoseStamped(point.position, Eigen::Quaterniond::Identity(), frame, stamp));
  }
  return msg;
}

visualization_msgs::Marker surfaceMesh(const terrain::Surface& surface,
                                       const Eigen::AlignedBox2d& area, double resolution,
                                       const std::string& frame, const ros::Time& stamp) {
  constexpr double kMaxCells = 1000.0;
  const Eigen::Vector2d size = area.sizes();
  if (!(resolution > 0.0) || !std::isfinite(resolution) || !area.min().allFinite() ||
      !area.max().allFinite() || !(size.minCoeff() > 0.0) ||
      size.maxCoeff() / resolution > kMaxCells) {
    std::ostringstream what;
    what << "surfaceMesh: the area [" << area.min().transpose() << "] - [" << area.max().transpose()
         << "] m and resolution = " << resolution
         << " m must be non-empty, positive, finite and give at most " << kMaxCells
         << " cells a side";
    throw std::invalid_argument(what.str());
  }
  const Eigen::Array2i cells = (size / resolution).array().ceil().cast<int>();
  const Eigen::Array2d spacing = size.array() / cells.cast<double>();
  const auto position = [&](int i, int j) {
    return Eigen::Vector2d(area.min().array() + Eigen::Array2d(i, j) * spacing);
  };
  Eigen::MatrixXd height(cells.x() + 1, cells.y() + 1);
  for (int i = 0; i <= cells.x(); ++i) {
    for (int j = 0; j <= cells.y(); ++j) {
      const Eigen::Vector2d xy = position(i, j);
      height(i, j) = surface.height(xy.x(), xy.y());
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
    const Eigen::Vector2d xy = position(i, j);
    msg.points.push_back(toPoint({xy.x(), xy.y(), height(i, j)}));
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
  for (int i = 0; i < cells.x(); ++i) {
    for (int j = 0; j < cells.y(); ++j) {
      for (const auto& [di, dj] : kCellTriangles) vertex(i + di, j + dj);
    }
  }
  return msg;
}
}  // namespace spherical_robots::conversions
