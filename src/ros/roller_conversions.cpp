#include "spherical_robots/ros/roller_conversions.hpp"

#include <Eigen/Geometry>

namespace spherical_robots::conversions {
namespace {

constexpr double kRollerWidth = 0.02;    // [m] of the roller markers
constexpr double kSlipArrowScale = 1.0;  // [m per m/s] of the slip arrows
const std::string kNamespace = "roller_drive";

}  // namespace

spherical_robots::RollerDrive toRollerDriveMsg(const roller::DriveState& state,
                                               const ros::Time& stamp) {
  spherical_robots::RollerDrive msg;
  msg.header.stamp = stamp;
  msg.roller_speed = {state.speeds.v1, state.speeds.v2};
  msg.slip = {state.slip[0], state.slip[1]};
  msg.omega = toVector3(state.omega);
  msg.speed = state.motion.speed;
  msg.direction = state.motion.direction;
  msg.rho = state.motion.rho;
  return msg;
}

visualization_msgs::MarkerArray rollerMarkers(const roller::RollerGeometry& geometry,
                                              double roller_radius,
                                              const roller::DriveState& state,
                                              const std::string& heading_frame,
                                              const ros::Time& stamp) {
  const Eigen::Vector3d centre(0.0, 0.0, geometry.radius());
  visualization_msgs::MarkerArray markers;
  for (std::size_t i = 0; i < 2; ++i) {
    const roller::RollerContact& contact = geometry.rollers()[i];
    const Eigen::Vector3d outward = contact.point.normalized();
    auto body = marker(kNamespace, static_cast<int>(i), visualization_msgs::Marker::CYLINDER,
                       heading_frame, stamp);
    body.pose.position = toPoint(centre + contact.point + roller_radius * outward);
    body.pose.orientation =
        toQuaternion(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), contact.axis));
    body.scale.x = body.scale.y = 2.0 * roller_radius;
    body.scale.z = kRollerWidth;
    body.color.r = 0.2f;
    body.color.g = 0.2f;
    body.color.b = 0.8f;
    markers.markers.push_back(body);

    // Slip ζ_i = S_i X_i (eq 27), drawn from the contact point.
    auto slip = marker(kNamespace, static_cast<int>(2 + i), visualization_msgs::Marker::ARROW,
                       heading_frame, stamp);
    const Eigen::Vector3d start = centre + contact.point;
    slip.points = {toPoint(start), toPoint(start + kSlipArrowScale * state.slip[i] * contact.tangent)};
    slip.scale.x = 0.01;
    slip.scale.y = 0.02;
    slip.scale.z = 0.02;
    slip.color.r = 1.0f;
    slip.color.g = 0.5f;
    markers.markers.push_back(slip);
  }
  return markers;
}

}  // namespace spherical_robots::conversions
