#pragma once
// Where two constraint rollers touch a sphere and which way they roll (Kimura, Ogata, Ishii 2019,
// eqs 2, 5, 6 and 12), checked once on construction so that the kinematics built on it
// (friction_drive.hpp) never divide by a vanishing quantity. Frames, angles and signs:
// docs/conventions.md, "Friction drive — Kimura et al. 2019".

#include <Eigen/Core>
#include <array>
#include <cstddef>

namespace spherical_robots::roller {

/// Threshold for every "is this zero?" test of the friction drive; the quantities compared with it
/// are dimensionless (a sine, a cosine, a component of a unit vector), so one value fits all.
/// 1e-9 keeps the 1/x factors below 1e9, where results still carry about 7 correct digits.
inline constexpr double kDegenerateTolerance = 1e-9;

/// A direction from the sphere's centre O (eq 12): azimuth θ_{1,i} [rad] from the x axis towards
/// y, elevation θ_{2,i} [rad] from the xy plane towards z.
struct SphericalDirection {
  double azimuth = 0.0;
  double elevation = 0.0;
};

/// One roller's contact frame, in the sphere frame Σ-xyz (origin O, z up). All unit vectors lie in
/// the tangent plane at P_i; (X_i, e) is its basis of eq 5 and (e_i, η_i) the roller's own.
struct RollerContact {
  double alpha = 0.0;       ///< α_i [rad]: tilt of the axis η_i out of span{P1, P2}
  Eigen::Vector3d point;    ///< P_i [m], |P_i| = r (eq 12)
  Eigen::Vector3d tangent;  ///< X_i = e × P_i / r, unit, in span{P1, P2} (eq 6)
  Eigen::Vector3d axis;     ///< η_i = X_i cos α_i + e sin α_i, unit (eq 5)
  /// e_i = P_i × η_i / r = e cos α_i − X_i sin α_i, unit: the roller surface at P_i moves with
  /// v_i^R = v_i e_i. This is the direction eq 2 needs (e_i × P_i = r η_i); the printed
  /// "e_i ∈ span{P_i, η_i}" is impossible for a roller rolling about η_i (docs/errata.md, K1).
  Eigen::Vector3d rolling_direction;
};

/// Two constraint rollers on a sphere of radius r: the contact points, the unit normal
/// e = P1 × P2 / ‖P1 × P2‖ of the plane through them and O (eq 6), and each roller's frame.
class RollerGeometry {
 public:
  /// @param radius sphere radius r [m].
  /// @param contact1, contact2 directions of P1 and P2 from O (eq 12) [rad].
  /// @param alpha1, alpha2 roller arrangement angles α1, α2 [rad] (eq 5); the paper keeps them in
  ///        [−π/2, π/2], but any finite value is accepted (α + π is the same roller turning the
  ///        other way round).
  /// @throw std::invalid_argument naming the problem: r not finite and > 0; a non-finite angle;
  ///        P1 and P2 parallel or antipodal (sin ∠P1OP2 <= kDegenerateTolerance: e and the
  ///        plane span{P1, P2} are undefined); |cos α_i| <= kDegenerateTolerance (the axis is
  ///        normal to span{P1, P2}, and eqs 8 and 22 divide by cos α_i).
  RollerGeometry(double radius, const SphericalDirection& contact1,
                 const SphericalDirection& contact2, double alpha1, double alpha2);

  double radius() const { return radius_; }  ///< r [m]
  /// rollers()[0] is the paper's roller 1 (P1, α1), rollers()[1] its roller 2.
  const std::array<RollerContact, 2>& rollers() const { return rollers_; }
  /// e, the unit normal of span{P1, P2} (eq 6); "upper" in the paper when e_z > 0.
  const Eigen::Vector3d& normal() const { return normal_; }
  /// ‖P1 × P2‖ = r² sin ∠P1OP2 [m²] (eq B.3), > 0.
  double crossNorm() const { return cross_norm_; }

 private:
  double radius_;
  Eigen::Vector3d normal_;
  double cross_norm_;
  std::array<RollerContact, 2> rollers_;
};

/// The point of the sphere of radius r [m] in direction `direction` (eq 12) [m].
/// @throw std::invalid_argument if r is not finite and > 0 or an angle is not finite.
Eigen::Vector3d spherePoint(double radius, const SphericalDirection& direction);

/// angle reduced to [0, period), for any finite angle and period > 0 (in whatever unit both are
/// given). Rounding never yields `period` itself: a result that would round up to it is 0.
double wrapToPeriod(double angle, double period);

}  // namespace spherical_robots::roller
