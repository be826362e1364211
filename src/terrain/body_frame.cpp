#include "spherical_robots/terrain/body_frame.hpp"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/terrain/tangent_frame.hpp"

namespace spherical_robots::terrain {
namespace {

// [m per m of |C_xy|]: a few ulps, where Newton's method stops; once it no longer gains, anything
// within kRoundingFloor is rounding (the solve amplifies it by up to 1 / (1 - R kappa)).
constexpr double kNewtonTolerance = 1e-14;
constexpr double kRoundingFloor = 1e-10;
constexpr int kMaxNewtonIterations = 30;

}  // namespace

BodyFrame::BodyFrame(const Surface& surface, double radius) : surface_(surface), radius_(radius) {
  requireSinglePointContact(surface, radius);
}

BodyPose BodyFrame::pose(const ContactGeometry& geometry) {
  const Eigen::Vector3d& heading = geometry.heading_frame.col(0);
  return {geometry.centre, yawRotation(std::atan2(heading.y(), heading.x()))};
}

BodyTwist BodyFrame::twist(const ContactGeometry& geometry, const TerrainStateRate& rate) const {
  const Eigen::Vector2d contact_rate(rate.x_dot, rate.y_dot);
  const Eigen::Vector3d centre_velocity = centreJacobian(geometry, radius_) * contact_rate;
  const Eigen::Matrix3d& frame = geometry.heading_frame;
  const Eigen::Vector3d& h = frame.col(0);
  const Eigen::Vector3d& n = frame.col(2);
  // R_L turns at (n x n') + spin n, so h' = spin l - (n' . h) n.
  const Eigen::Vector3d normal_rate = normalJacobian(geometry) * contact_rate;
  const double spin = rate.psi_dot + tangentFrameSpin(n, normal_rate);
  const Eigen::Vector3d heading_rate = spin * frame.col(1) - normal_rate.dot(h) * n;
  const double yaw = std::atan2(h.y(), h.x());
  BodyTwist twist;
  twist.linear = Eigen::AngleAxisd(-yaw, Eigen::Vector3d::UnitZ()) * centre_velocity;
  twist.angular.z() = (h.x() * heading_rate.y() - h.y() * heading_rate.x()) / h.head<2>().squaredNorm();
  return twist;
}

TerrainState BodyFrame::state(const BodyPose& pose, double phi) const {
  if (!pose.centre.allFinite()) throw std::invalid_argument("body centre is not finite");
  requireFinite(phi, "tilt phi [rad]");
  const double yaw = yawOf(pose.orientation);
  const Eigen::Vector2d target = pose.centre.head<2>();
  const double scale = 1.0 + target.norm();
  // Exact on a plane, where n is the same everywhere.
  Eigen::Vector2d contact =
      target - radius_ * surfaceNormal(surface_.gradient(target.x(), target.y())).head<2>();
  ContactGeometry geometry;
  double last_residual = std::numeric_limits<double>::infinity();
  for (int iteration = 0;; ++iteration) {
    if (!contact.allFinite() || iteration > kMaxNewtonIterations) {
      std::ostringstream what;
      what << "no contact point under the body centre (" << target.x() << ", " << target.y()
           << ") m: Newton's method did not converge in " << kMaxNewtonIterations << " iterations";
      throw std::invalid_argument(what.str());
    }
    geometry = contactGeometry(surface_, radius_, {contact.x(), contact.y(), 0.0, 0.0});
    const double residual_norm = (geometry.centre.head<2>() - target).norm();
    if (residual_norm <= kNewtonTolerance * scale ||
        (residual_norm >= last_residual && residual_norm <= kRoundingFloor * scale))
      break;
    last_residual = residual_norm;
    contact -= centreJacobian(geometry, radius_).topRows<2>().partialPivLu().solve(
        geometry.centre.head<2>() - target);
  }
  // The yaw's direction lifted onto the tangent plane: h = (d, f_x d_x + f_y d_y), unnormalised.
  const Eigen::Vector2d direction(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector3d heading(direction.x(), direction.y(), geometry.gradient.dot(direction));
  const Eigen::Matrix3d tangent = tangentFrame(geometry.gradient);
  return {contact.x(), contact.y(), std::atan2(heading.dot(tangent.col(1)), heading.dot(tangent.col(0))),
          phi};
}

}  // namespace spherical_robots::terrain
