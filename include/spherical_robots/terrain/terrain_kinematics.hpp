#pragma once
// Kinematics of a sphere rolling over z = f(x, y) for the four robot types (paper eqs 28-52),
// in the sign convention of docs/conventions.md.

#include <Eigen/Core>
#include <string>

#include "spherical_robots/core/enum_names.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/surface.hpp"

namespace spherical_robots::terrain {

/// What the drive rates move.
enum class ContactModel {
  /// (R theta_dot, -R phi_dot) is the velocity of the contact point P0 in F_L, as the paper
  /// integrates it (eqs 28, 33).
  Paper,
  /// The rates are the shell's body rates: they set the velocity of the sphere's centre,
  /// V = Omega x R n, and P0 follows from the surface's curvature, (I + R dn/dP0) dP0/dt = V.
  /// The heading turns about n at exactly the realised turn rate, so psi (measured from the
  /// tangent frame) also absorbs that frame's own turning about n as P0 moves.
  Rolling,
};

/// "paper" | "rolling". @throw std::invalid_argument on an unknown name.
inline constexpr EnumNames<ContactModel, 2> kContactModelNames = {
    {{ContactModel::Paper, "paper"}, {ContactModel::Rolling, "rolling"}}};
inline ContactModel contactModelFromString(const std::string& name) {
  return enumFromName(kContactModelNames, name, "contact model");
}
inline std::string toString(ContactModel model) { return enumName(kContactModelNames, model); }

/// The configuration (x0, y0, psi, phi): contact point in the plane [m], heading psi [rad]
/// right-handed about n relative to the tangent frame, and RS tilt phi [rad] (0 for other types).
/// The contact point's height is always f(x0, y0), so it never drifts off the surface.
struct TerrainState {
  double x = 0.0;
  double y = 0.0;
  double psi = 0.0;
  double phi = 0.0;
};

/// d/dt of TerrainState.
struct TerrainStateRate {
  double x_dot = 0.0;
  double y_dot = 0.0;
  double psi_dot = 0.0;
  double phi_dot = 0.0;
};

/// Geometry of the robot at one state, in the world frame.
struct ContactGeometry {
  Eigen::Vector3d contact_point = Eigen::Vector3d::Zero();  ///< P0 [m]
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();         ///< O_Sp = P0 + R n (eq 51) [m]
  Eigen::Matrix3d heading_frame = Eigen::Matrix3d::Identity();  ///< R_L, columns (h, l, n)
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();       ///< (f_x, f_y) at P0
  Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();        ///< f's Hessian at P0 [1/m]
};

/// The geometry at a state of a sphere of `radius` [m] on `surface`.
/// @throw std::invalid_argument if the state is not finite.
ContactGeometry contactGeometry(const Surface& surface, double radius, const TerrainState& state);

/// [dn/dx dn/dy] [1/m] of the unit normal as a function of the contact point, at `geometry`.
Eigen::Matrix<double, 3, 2> normalJacobian(const ContactGeometry& geometry);

/// [dC/dx dC/dy] [-] of the centre C(x, y) = P0 + R n(P0) (eq 51) as a function of the contact
/// point, at `geometry`, for a sphere of `radius` [m].
Eigen::Matrix<double, 3, 2> centreJacobian(const ContactGeometry& geometry, double radius);

class TerrainKinematics {
 public:
  /// @param radius R [m] > 0; @param tilt_limit RS |phi| limit [rad] in (0, pi/2).
  /// @throw std::invalid_argument on a bad radius or limit, or if the surface/radius pair breaks
  /// single-point contact.
  TerrainKinematics(const Surface& surface, RobotType type, double radius, ContactModel model,
                    double tilt_limit);

  RobotType type() const { return type_; }
  ContactModel model() const { return model_; }
  double radius() const { return radius_; }
  double tiltLimit() const { return tilt_limit_; }
  const Surface& surface() const { return surface_; }

  ContactGeometry geometry(const TerrainState& state) const;

  /// The rates the robot actually realises from commanded rates: unactuated rates are zero,
  /// RS turns by psi_dot = -alpha_dot sin(phi) (eq 44), and the RS tilt stops at its limit.
  DriveRates realisedRates(const TerrainState& state, const DriveRates& commanded) const;

  /// dState/dt for commanded rates. @throw std::invalid_argument on non-finite input.
  TerrainStateRate stateRate(const TerrainState& state, const DriveRates& commanded) const;

  /// Same, reusing geometry already computed for this state.
  TerrainStateRate stateRate(const TerrainState& state, const ContactGeometry& geometry,
                             const DriveRates& commanded) const;

  /// Same, for rates that realisedRates() already returned for this state (realising them again
  /// would change nothing).
  TerrainStateRate realisedStateRate(const TerrainState& state, const ContactGeometry& geometry,
                                     const DriveRates& realised) const;

  /// The shell's angular velocity in the world frame [rad/s]:
  /// theta_dot l + phi_dot h + psi_dot n (eq 46 for RS: alpha_dot (cos phi l + sin phi n) + ...).
  Eigen::Vector3d shellAngularVelocity(const TerrainState& state, const DriveRates& commanded) const;

  /// Velocity [m/s] of the sphere's centre O_Sp = P0 + R n (eq 51): Omega x R n in the rolling
  /// model, (I + R dn/dP0) dP0/dt in the paper model.
  Eigen::Vector3d centreVelocity(const TerrainState& state, const DriveRates& commanded) const;

  /// Clamps phi into the tilt limit (RS) after an integration step.
  TerrainState constrain(const TerrainState& state) const;

 private:
  const Surface& surface_;
  RobotType type_;
  double radius_;
  ContactModel model_;
  double tilt_limit_;
};

}  // namespace spherical_robots::terrain
