#pragma once
// Kinematics of a sphere rolling over z = f(x, y) for the four robot types (paper eqs 28-52),
// in the sign convention of docs/conventions.md.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>

#include "spherical_robots/core/enum_names.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/tangent_frame.hpp"

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

/// The geometry at a state of a sphere of `radius` [m] on `surface` (a Surface, or a final
/// surface class, whose evaluate() is then called directly and may be inlined).
/// @throw std::invalid_argument if the state is not finite.
template <typename SurfaceType>
ContactGeometry contactGeometry(const SurfaceType& surface, double radius,
                                const TerrainState& state);

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

  /// @throw std::invalid_argument if the state is not finite.
  ContactGeometry geometry(const TerrainState& state) const;

  /// The rates the robot actually realises from commanded rates: unactuated rates are zero,
  /// RS turns by psi_dot = -alpha_dot sin(phi) (eq 44), and the RS tilt stops at its limit.
  /// @throw std::invalid_argument on non-finite rates.
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
  /// realisedStateRate's rolling model: the contact point's rate for the centre's velocity.
  TerrainStateRate rollingStateRate(const TerrainState& state, const ContactGeometry& geometry,
                                    const Eigen::Vector3d& velocity, TerrainStateRate rate) const;

  const Surface& surface_;
  /// surface_ if it is the paper's eq 59, which geometry() then evaluates inline, not through
  /// the vtable (at every RK stage of a batch run); nullptr for other surfaces.
  const CosineSurface* cosine_surface_;
  RobotType type_;
  std::array<bool, 3> actuated_;  ///< actuatedRates(type_)
  double radius_;
  ContactModel model_;
  double tilt_limit_;
};

// Inline below: the closed loop calls these at every RK stage, where out of line their results
// went through memory on the chain of operations from one stage to the next.
namespace terrain_kinematics_detail {

/// @throw std::invalid_argument naming the values (out of line: the checks stay compares).
[[noreturn]] void rejectState(const TerrainState& state);
[[noreturn]] void rejectRates(const DriveRates& rates);

inline void requireFinite(const TerrainState& state) {
  if (!allFinite(state.x, state.y, state.psi, state.phi)) rejectState(state);
}

inline void requireFinite(const DriveRates& rates) {
  if (!allFinite(rates.roll_rate, rates.lateral_rate, rates.turn_rate)) rejectRates(rates);
}

}  // namespace terrain_kinematics_detail

template <typename SurfaceType>
inline ContactGeometry contactGeometry(const SurfaceType& surface, double radius,
                                       const TerrainState& state) {
  terrain_kinematics_detail::requireFinite(state);
  const SurfacePoint point = surface.evaluate(state.x, state.y);
  ContactGeometry geometry{Eigen::Vector3d(state.x, state.y, point.height), Eigen::Vector3d(),
                           headingFrame(point.gradient, state.psi), point.gradient, point.hessian};
  geometry.centre = geometry.contact_point + radius * geometry.heading_frame.col(2);  // eq 51
  return geometry;
}

inline ContactGeometry TerrainKinematics::geometry(const TerrainState& state) const {
  if (cosine_surface_ != nullptr) return contactGeometry(*cosine_surface_, radius_, state);
  return contactGeometry(surface_, radius_, state);
}

inline DriveRates TerrainKinematics::realisedRates(const TerrainState& state,
                                                   const DriveRates& commanded) const {
  terrain_kinematics_detail::requireFinite(commanded);
  DriveRates realised = keepActuated(actuated_, commanded);
  if (type_ == RobotType::RollingAndSteering) {
    const bool pushing_past_limit = (state.phi >= tilt_limit_ && realised.lateral_rate > 0.0) ||
                                    (state.phi <= -tilt_limit_ && realised.lateral_rate < 0.0);
    if (pushing_past_limit) realised.lateral_rate = 0.0;
    realised.turn_rate = -realised.roll_rate * std::sin(state.phi);  // eq 44
  }
  return realised;
}

inline TerrainStateRate TerrainKinematics::realisedStateRate(const TerrainState& state,
                                                             const ContactGeometry& geometry,
                                                             const DriveRates& rates) const {
  // Eqs 33 and 48: the rolling velocity in F_L.
  const double forward = type_ == RobotType::RollingAndSteering
                             ? radius_ * rates.roll_rate * std::cos(state.phi)
                             : radius_ * rates.roll_rate;
  const double leftward = -radius_ * rates.lateral_rate;
  const Eigen::Matrix3d& frame = geometry.heading_frame;
  const Eigen::Vector3d velocity = forward * frame.col(0) + leftward * frame.col(1);  // eq 28

  TerrainStateRate rate;
  rate.psi_dot = rates.turn_rate;
  rate.phi_dot = type_ == RobotType::RollingAndSteering ? rates.lateral_rate : 0.0;
  if (model_ == ContactModel::Paper) {
    rate.x_dot = velocity.x();
    rate.y_dot = velocity.y();
    return rate;
  }
  return rollingStateRate(state, geometry, velocity, rate);
}

}  // namespace spherical_robots::terrain
