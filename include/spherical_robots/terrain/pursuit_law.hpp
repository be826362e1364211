#pragma once
// What every terrain tracking law shares: the choice between them, the tracking error of eqs
// 53-54, and the interface through which the batch run and the controller node drive either.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>

#include "spherical_robots/core/enum_names.hpp"
#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots::terrain {

/// Which law turns the tracking error into drive rates.
enum class PursuitLaw {
  Paper,   ///< eqs 55-58 as printed (signs per docs/conventions.md): PurePursuitController
  Smooth,  ///< docs/conventions.md, "The smooth law": SmoothPursuitController
};

/// "paper" | "smooth". @throw std::invalid_argument naming the value and the allowed ones.
inline constexpr EnumNames<PursuitLaw, 2> kPursuitLawNames = {
    {{PursuitLaw::Paper, "paper"}, {PursuitLaw::Smooth, "smooth"}}};
inline PursuitLaw pursuitLawFromString(const std::string& name) {
  return enumFromName(kPursuitLawNames, name, "pursuit law");
}
inline std::string toString(PursuitLaw law) { return enumName(kPursuitLawNames, law); }

/// The tracking error of eqs 53-54, with zeta signed.
struct TrackingError {
  Eigen::Vector3d error = Eigen::Vector3d::Zero();  ///< e_t = p_d - P0 [m] (eq 53)
  double norm = 0.0;                                ///< |e_t| [m]
  /// Angle [rad] in (-pi, pi] from h to e_t's projection on the tangent plane, right-handed
  /// about n: positive when the target is to the left (eq 54 gives only its magnitude). 0 when
  /// e_t has no component in the tangent plane (below 1e-12 |e_t|, i.e. round-off).
  double zeta = 0.0;
};

/// e_t, |e_t| and, if with_zeta, zeta (otherwise left 0: its atan2 is a fifth of a closed-loop
/// stage, wasted on a law that does not read it, PursuitController::readsZeta).
/// @throw std::invalid_argument on a non-finite desired point.
inline TrackingError trackingError(const ContactGeometry& geometry,
                                   const Eigen::Vector3d& desired, bool with_zeta = true);

/// A tracking law for one robot type. Stateless: the command is a function of the robot's state
/// and the reference at one instant, so the batch run can evaluate it at every RK stage.
class PursuitController {
 public:
  virtual ~PursuitController() = default;

  virtual RobotType type() const = 0;

  /// Which of the reference's velocities the law's feed-forward takes (liftOntoSurface).
  virtual VelocityWindow velocityWindow() const = 0;

  /// Whether command() reads TrackingError::zeta; if not, the batch run's RK stages leave it
  /// uncomputed.
  virtual bool readsZeta() const = 0;

  /// Drive-rate set-points [rad/s].
  /// @param geometry the robot's contact geometry; @param tilt the RS tilt phi [rad] (0 for the
  /// other types); @param error trackingError(geometry, p_d(t));
  /// @param desired_velocity the path's velocity [m/s] over velocityWindow(), lifted.
  /// @throw std::invalid_argument on non-finite input.
  virtual DriveRates command(const ContactGeometry& geometry, double tilt,
                             const TrackingError& error,
                             const Eigen::Vector3d& desired_velocity) const = 0;
};

// Inline: the closed loop takes the error at every RK stage, where out of line it went through
// memory on the chain of operations from one stage to the next.
namespace pursuit_law_detail {
/// @throw std::invalid_argument (out of line: the check stays a compare).
[[noreturn]] void rejectDesiredPoint();
}  // namespace pursuit_law_detail

// Eq 53, and eq 54 signed: atan2 of e_t's components along l and h.
inline TrackingError trackingError(const ContactGeometry& geometry,
                                   const Eigen::Vector3d& desired, bool with_zeta) {
  if (!allFinite(desired.x(), desired.y(), desired.z())) pursuit_law_detail::rejectDesiredPoint();
  TrackingError result;
  result.error = desired - geometry.contact_point;
  result.norm = result.error.norm();
  if (!with_zeta) return result;
  const double along_heading = result.error.dot(geometry.heading_frame.col(0));
  const double along_left = result.error.dot(geometry.heading_frame.col(1));
  // Along n the direction in the plane is round-off, not information. hypot(a, b) is never below
  // max(|a|, |b|), so the larger component alone settles the usual case without the slow hypot.
  const double round_off = 1e-12 * result.norm;
  if (std::max(std::abs(along_heading), std::abs(along_left)) > round_off ||
      std::hypot(along_heading, along_left) > round_off) {
    result.zeta = std::atan2(along_left, along_heading);
  }
  return result;
}

}  // namespace spherical_robots::terrain
