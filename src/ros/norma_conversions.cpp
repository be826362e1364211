#include "spherical_robots/ros/norma_conversions.hpp"

#include <Eigen/Geometry>
#include <limits>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"

namespace spherical_robots::conversions {

const std::vector<std::string>& normaActuatorNames() {
  static const std::vector<std::string> names = {"pendulum_motor", "slider_motor"};
  return names;
}

spherical_robots::NormaState toNormaStateMsg(const norma::NormaState& state,
                                             const norma::Efforts& driving, double energy,
                                             const ros::Time& stamp) {
  spherical_robots::NormaState msg;
  msg.header.stamp = stamp;
  for (int i = 0; i < 4; ++i) {
    msg.q[i] = state.q(i);
    msg.qd[i] = state.qd(i);
  }
  msg.x = state.x;
  msg.y = state.y;
  msg.psi = state.psi;
  msg.torque = driving.torque;
  msg.force = driving.force;
  msg.energy = energy;
  return msg;
}

namespace {

/// urdf/norma.urdf's joints: φ, θ, α, δ; q is (θ, α, φ, δ).
const std::vector<std::string> kJoints = {"tilt_joint", "shell_joint", "pendulum_joint",
                                          "slider_joint"};

}  // namespace

norma::NormaMeasurement normaPoseFromOdometry(const nav_msgs::Odometry& odom) {
  norma::NormaMeasurement pose;
  const Eigen::Vector3d position = fromPoint(odom.pose.pose.position, "odom pose.position");
  pose.x = position.x();
  pose.y = position.y();
  pose.psi = yawOf(checkedQuaternion(odom.pose.pose.orientation, "odom pose.orientation"));
  return pose;
}

norma::NormaMeasurement withNormaJoints(norma::NormaMeasurement pose,
                                        const sensor_msgs::JointState& joints) {
  constexpr double kAnyFinite = std::numeric_limits<double>::max();  // the loop bounds them
  const std::vector<double> q = positionsByName(joints, kJoints, kAnyFinite);
  const std::vector<double> qd = velocitiesByName(joints, kJoints, kAnyFinite);
  pose.q = norma::Vector4(q[1], q[2], q[0], q[3]);
  pose.qd = norma::Vector4(qd[1], qd[2], qd[0], qd[3]);
  return pose;
}

sensor_msgs::JointState normaJointState(const norma::NormaState& state, const ros::Time& stamp) {
  const norma::Vector4& q = state.q;
  const norma::Vector4& qd = state.qd;
  return jointState(kJoints, {q(2), q(0), q(1), q(3)}, {qd(2), qd(0), qd(1), qd(3)}, {}, stamp);
}

sensor_msgs::JointState normaEffortCommand(double torque, double force, const ros::Time& stamp) {
  return jointState(normaActuatorNames(), {}, {}, {torque, force}, stamp);
}

spherical_robots::TrackingError toNormaTrackingErrorMsg(const norma::PathPoint& reference, double x,
                                                        double y, double error_norm, double zeta,
                                                        const std::string& frame,
                                                        const ros::Time& stamp) {
  spherical_robots::TrackingError msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  msg.desired = toPoint({reference.x, reference.y, 0.0});
  msg.desired_velocity = toVector3({reference.x_dot, reference.y_dot, 0.0});
  msg.error = toVector3({reference.x - x, reference.y - y, 0.0});
  msg.error_norm = error_norm;
  msg.zeta = zeta;
  return msg;
}

nav_msgs::Path lissajousPathMsg(double period, int samples, const std::string& frame,
                                const ros::Time& stamp) {
  nav_msgs::Path path;
  path.header.frame_id = frame;
  path.header.stamp = stamp;
  for (int k = 0; k <= samples; ++k) {
    const norma::PathPoint p = norma::lissajousPath(period * k / samples);
    path.poses.push_back(
        toPoseStamped({p.x, p.y, 0.0}, Eigen::Quaterniond::Identity(), frame, stamp));
  }
  return path;
}

}  // namespace spherical_robots::conversions
