#pragma once
// The robot's non-rolling body, REP 105's base_link, and the terrain model's state, both ways
// (docs/conventions.md, "Frames"). base_link sits at the sphere's centre C = P0 + R n(P0) (eq 51),
// gravity-aligned: z up, x the heading h projected on the horizontal plane. Odometry carries its
// pose and twist; a controller that reads odometry recovers the contact point and psi from them
// through the terrain model, as the plant's own state would give them.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots::terrain {

/// base_link in the odometry frame.
struct BodyPose {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< C [m]
  /// odom <- base_link: a turn by the body's yaw about z.
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// base_link's twist in base_link's own axes (x forward, y left, z up).
struct BodyTwist {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   ///< the centre's velocity [m/s]
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  ///< (0, 0, yaw rate) [rad/s]
};

/// Between the state (x0, y0, psi) of a sphere of radius R on a surface and its body's pose and
/// twist.
class BodyFrame {
 public:
  /// The surface must outlive the frame. @throw std::invalid_argument unless radius [m] is finite
  /// and > 0 and the sphere keeps single-point contact on the surface (R kappa < 1), which makes
  /// C(P0) one-to-one.
  BodyFrame(const Surface& surface, double radius);

  /// The body's pose at a geometry (contactGeometry of this surface and radius).
  static BodyPose pose(const ContactGeometry& geometry);

  /// The body's twist at a geometry for the state's rate of change: the centre's velocity
  /// [dC/dx dC/dy] (x0', y0') and the yaw rate of h's horizontal projection, h turning about n at
  /// psi' plus the tangent frame's own turning (tangentFrameSpin) and tilting with n.
  BodyTwist twist(const ContactGeometry& geometry, const TerrainStateRate& rate) const;

  /// The state whose body has this pose, with RS tilt `phi` [rad]: the contact point solves
  /// (C_x, C_y) = P0_xy + R n_xy(P0) by Newton's method (to 1e-14 m per metre of |C|, or
  /// rounding), and the
  /// yaw's horizontal direction d is lifted onto the tangent plane there, h ∝ (d, f_x d_x + f_y d_y),
  /// psi = atan2(h . j_T, h . i_T). The yaw is yawOf(orientation) (which need not be normalised);
  /// the pose's height and its roll and pitch are not used: the terrain fixes them (a planar
  /// odometry source has none).
  /// @throw std::invalid_argument if the pose is not finite or Newton's method does not converge.
  TerrainState state(const BodyPose& pose, double phi) const;

  double radius() const { return radius_; }

 private:
  const Surface& surface_;
  double radius_;
};

}  // namespace spherical_robots::terrain
