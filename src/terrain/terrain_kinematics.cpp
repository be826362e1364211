#include "spherical_robots/terrain/terrain_kinematics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/terrain/tangent_frame.hpp"

namespace spherical_robots::terrain {
namespace terrain_kinematics_detail {

void rejectState(const TerrainState& state) {
  std::ostringstream message;
  message << "terrain kinematics: state is not finite (x=" << state.x << ", y=" << state.y
          << ", psi=" << state.psi << ", phi=" << state.phi << ")";
  throw std::invalid_argument(message.str());
}

void rejectRates(const DriveRates& rates) {
  std::ostringstream message;
  message << "terrain kinematics: drive rates are not finite (roll=" << rates.roll_rate
          << ", lateral=" << rates.lateral_rate << ", turn=" << rates.turn_rate << ")";
  throw std::invalid_argument(message.str());
}

}  // namespace terrain_kinematics_detail

TerrainKinematics::TerrainKinematics(const Surface& surface, RobotType type, double radius,
                                     ContactModel model, double tilt_limit)
    : surface_(surface), cosine_surface_(dynamic_cast<const CosineSurface*>(&surface)),
      type_(type), actuated_(actuatedRates(type)), radius_(radius), model_(model),
      tilt_limit_(tilt_limit) {
  requireSinglePointContact(surface, radius);
  if (!std::isfinite(tilt_limit) || tilt_limit <= 0.0 || tilt_limit >= M_PI / 2.0) {
    throw std::invalid_argument("RS tilt limit must be in (0, pi/2) rad, got " +
                                std::to_string(tilt_limit));
  }
}

// With N = (-f_x, -f_y, 1): dn/dx_j = (I - n n^T) dN/dx_j / |N|.
Eigen::Matrix<double, 3, 2> normalJacobian(const ContactGeometry& geometry) {
  const Eigen::Vector3d& n = geometry.heading_frame.col(2);
  const Eigen::Matrix2d& hessian = geometry.hessian;
  const double normal_length = std::sqrt(1.0 + geometry.gradient.squaredNorm());
  const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - n * n.transpose();
  Eigen::Matrix<double, 3, 2> unnormalised;
  unnormalised << -hessian(0, 0), -hessian(0, 1), -hessian(1, 0), -hessian(1, 1), 0.0, 0.0;
  return projector * unnormalised / normal_length;
}

Eigen::Matrix<double, 3, 2> centreJacobian(const ContactGeometry& geometry, double radius) {
  Eigen::Matrix<double, 3, 2> contact_jacobian;
  contact_jacobian << 1.0, 0.0, 0.0, 1.0, geometry.gradient.x(), geometry.gradient.y();
  return contact_jacobian + radius * normalJacobian(geometry);
}

TerrainStateRate TerrainKinematics::stateRate(const TerrainState& state,
                                              const DriveRates& commanded) const {
  return stateRate(state, geometry(state), commanded);
}

TerrainStateRate TerrainKinematics::stateRate(const TerrainState& state,
                                              const ContactGeometry& geometry,
                                              const DriveRates& commanded) const {
  return realisedStateRate(state, geometry, realisedRates(state, commanded));
}

TerrainStateRate TerrainKinematics::rollingStateRate(const TerrainState& state,
                                                     const ContactGeometry& geometry,
                                                     const Eigen::Vector3d& velocity,
                                                     TerrainStateRate rate) const {
  // Rolling: velocity is the centre's; solve [dC/dx dC/dy] (x', y') = velocity, which lies in
  // the tangent plane like both columns.
  const Eigen::Matrix<double, 3, 2> jacobian = centreJacobian(geometry, radius_);
  const Eigen::Matrix2d gram = jacobian.transpose() * jacobian;
  const double determinant = gram.determinant();
  if (!(determinant > 1e-12 * gram.trace() * gram.trace())) {
    std::ostringstream message;
    message << "rolling contact is degenerate at (" << state.x << ", " << state.y
            << "): the sphere's centre surface folds (R * curvature >= 1)";
    throw std::invalid_argument(message.str());
  }
  const Eigen::Vector2d contact_rate = gram.inverse() * (jacobian.transpose() * velocity);
  rate.x_dot = contact_rate.x();
  rate.y_dot = contact_rate.y();
  // The minimal-rotation tangent frame turns about n at z . (n' x n) / (1 + n_z) as n changes;
  // psi, measured from it, must turn the other way for the heading to turn at turn_rate.
  rate.psi_dot -=
      tangentFrameSpin(geometry.heading_frame.col(2), normalJacobian(geometry) * contact_rate);
  return rate;
}

Eigen::Vector3d TerrainKinematics::centreVelocity(const TerrainState& state,
                                                  const DriveRates& commanded) const {
  const ContactGeometry contact = geometry(state);
  const TerrainStateRate rate = stateRate(state, contact, commanded);
  return centreJacobian(contact, radius_) * Eigen::Vector2d(rate.x_dot, rate.y_dot);
}

// Eq 46 (for RS, the shell turns by psi_dot = -alpha_dot sin(phi) about n, cancelling the tilted
// axle's n component, so Omega lies in the tangent plane as a rolling cone's must).
Eigen::Vector3d TerrainKinematics::shellAngularVelocity(const TerrainState& state,
                                                        const DriveRates& commanded) const {
  const DriveRates rates = realisedRates(state, commanded);
  const Eigen::Matrix3d frame = geometry(state).heading_frame;
  if (type_ == RobotType::RollingAndSteering) {
    return rates.lateral_rate * frame.col(0) + rates.roll_rate * std::cos(state.phi) * frame.col(1);
  }
  return rates.lateral_rate * frame.col(0) + rates.roll_rate * frame.col(1) +
         rates.turn_rate * frame.col(2);
}

TerrainState TerrainKinematics::constrain(const TerrainState& state) const {
  TerrainState constrained = state;
  if (type_ == RobotType::RollingAndSteering) {
    constrained.phi = std::clamp(state.phi, -tilt_limit_, tilt_limit_);
  } else {
    constrained.phi = 0.0;
  }
  return constrained;
}

}  // namespace spherical_robots::terrain
