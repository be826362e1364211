#pragma once
// The smooth tracking law (docs/conventions.md, "The smooth law"): every type steers by one
// desired velocity of the contact point, u = w + c(e_t), the reference's velocity w averaged over
// a short window (the feed-forward |p_d'|/R of eqs 55/57/58, kept as a vector) plus a bounded
// correction towards p_d. u is a smooth function of the state and time, so the commands are too;
// eqs 55-58 instead steer by the direction zeta of e_t, which flips across +-pi as e_t -> 0.

#include <Eigen/Core>
#include <cmath>

#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/terrain/pursuit_law.hpp"

namespace spherical_robots::terrain {

/// Gains of the smooth law; each type reads the ones it uses. The member defaults are 3R's and
/// 2R's (and RS's for the tilt, which only RS has); defaultSmoothGains() gives every type's.
struct SmoothPursuitGains {
  /// tau [s] >= 0: w is the mean of the path's velocity over [t + lead - tau/2, t + lead + tau/2],
  /// so a corner turns the feed-forward over tau instead of at once.
  double window = 0.5;
  /// [s] >= 0: for types that turn to follow u, 1 / heading_gain makes the heading loop exact
  /// on an arc (u then leads the tangent by the angle the loop needs); 0 for 3R and 2R.
  double lead = 0.0;
  double approach_speed = 0.5;  ///< v_c [m/s] > 0: the bound of the correction c, far from p_d
  /// K_a [1/s] > 0: the correction's slope at e_t = 0 along the path (the direction of w).
  double along_gain = 4.0;
  double cross_gain = 3.0;    ///< K_c [1/s] > 0: the same across the path
  double heading_gain = 2.0;  ///< k_h [1/s] >= 0: turn rate per unit sine of u off h (3R, RT, RS)
  double tilt_gain = 3.0;     ///< k_t [1/s] > 0: RS tilt servo
  /// r_t [rad/s] > 0: the RS tilt rate's smooth bound, r_t tanh(k_t (phi* - phi) / r_t), so that
  /// a swing of the tilt stays within what a tilt actuator's acceleration limit can follow.
  double max_tilt_rate = 1.0;
  double max_tilt = 0.8;  ///< [rad] > 0: bound of the RS tilt set-point, inside the limit
  /// v_e [m/s] > 0: where |u| falls below it, the steering towards u fades out smoothly (u's
  /// direction means nothing at u = 0).
  double min_speed = 0.01;
};

/// The default gains of a robot type (docs/conventions.md, "The smooth law"; also in
/// config/terrain.yaml): RT and RS lead their window by 1 / heading_gain and average over a
/// longer one, RT turns harder, RS approaches slower (its turns are slow), corrects less across
/// the path and keeps its steering regularised over more speed.
SmoothPursuitGains defaultSmoothGains(RobotType type);

/// Throws std::invalid_argument naming the first gain that is non-finite or out of its range,
/// with its value and the limit.
void validate(const SmoothPursuitGains& gains);

class SmoothPursuitController final : public PursuitController {
 public:
  /// @param radius R [m] > 0; @param tilt_limit the RS tilt limit [rad], which
  /// gains.max_tilt must stay below. @throw std::invalid_argument on bad gains, radius or limit.
  SmoothPursuitController(RobotType type, const SmoothPursuitGains& gains, double radius,
                          double tilt_limit);

  RobotType type() const override { return type_; }
  VelocityWindow velocityWindow() const override { return {gains_.lead, gains_.window}; }
  bool readsZeta() const override { return false; }
  const SmoothPursuitGains& gains() const { return gains_; }

  /// The desired velocity u = w + c [m/s], before projection: c = v_c k / (v_c + |k|) with
  /// k = K_c e_t + (K_a - K_c) (e_t . t) t, t = w / sqrt(|w|^2 + v_e^2) along the path.
  Eigen::Vector3d desiredVelocity(const TrackingError& error,
                                  const Eigen::Vector3d& desired_velocity) const;

  /// Inline (below): called on a SmoothPursuitController itself, as TerrainSimulation does at
  /// every RK stage, it is inlined instead of taking its input and returning its rates through
  /// memory.
  inline DriveRates command(const ContactGeometry& geometry, double tilt,
                            const TrackingError& error,
                            const Eigen::Vector3d& desired_velocity) const override;

 private:
  /// c = v_c k / D (desiredVelocity's) in its factors: command() projects k onto the heading
  /// frame while D's square root, the slow part, is under way, and divides by D only where the
  /// direction of u does not need it.
  struct Correction {
    Eigen::Vector3d linear;  ///< k [m/s]
    double denominator;      ///< D = v_c + |k| [m/s]
  };
  Correction correction(const TrackingError& error, const Eigen::Vector3d& desired_velocity) const;
  /// @throw std::invalid_argument naming command()'s input (out of line: the check stays compares).
  [[noreturn]] static void rejectInput(double tilt, const TrackingError& error,
                                       const Eigen::Vector3d& desired_velocity);

  RobotType type_;
  SmoothPursuitGains gains_;
  // Constants of command(), which runs at every RK stage: a multiplication, not a division or sin.
  double inverse_radius_;  ///< 1 / R [1/m]
  double max_tilt_sine_;  ///< sin(max_tilt)
};

// Linear in e_t near p_d (stiffer along the path, where only the speed responds, than across,
// where types that must turn respond through their heading), never faster than v_c far from it.
inline SmoothPursuitController::Correction SmoothPursuitController::correction(
    const TrackingError& error, const Eigen::Vector3d& desired_velocity) const {
  const Eigen::Vector3d along =
      desired_velocity *
      (1.0 / std::sqrt(desired_velocity.squaredNorm() + gains_.min_speed * gains_.min_speed));
  const Eigen::Vector3d linear = gains_.cross_gain * error.error +
                                 (gains_.along_gain - gains_.cross_gain) *
                                     error.error.dot(along) * along;
  return {linear, gains_.approach_speed + linear.norm()};
}

inline DriveRates SmoothPursuitController::command(const ContactGeometry& geometry, double tilt,
                                                   const TrackingError& error,
                                                   const Eigen::Vector3d& desired_velocity) const {
  const Eigen::Vector3d& e = error.error;
  const Eigen::Vector3d& w = desired_velocity;
  if (!allFinite(error.norm, e.x(), e.y(), e.z(), w.x(), w.y(), w.z(), tilt)) {
    rejectInput(tilt, error, desired_velocity);
  }
  // The robot moves in the tangent plane: u's components along h and l. With D = v_c + |k|,
  // D u = D w + v_c k has u's direction without a division by D, which the turn, at the end of
  // the chain of operations from one RK stage to the next, then does not wait for.
  const Correction c = correction(error, desired_velocity);
  const Eigen::Vector3d& h = geometry.heading_frame.col(0);
  const Eigen::Vector3d& l = geometry.heading_frame.col(1);
  const double approach_speed = gains_.approach_speed;
  const double forward_times_d =
      c.denominator * desired_velocity.dot(h) + approach_speed * c.linear.dot(h);
  const double leftward_times_d =
      c.denominator * desired_velocity.dot(l) + approach_speed * c.linear.dot(l);
  const double inverse_d = 1.0 / c.denominator;
  const double forward = forward_times_d * inverse_d;
  const double leftward = leftward_times_d * inverse_d;
  // Turn towards u: k_h times the sine of the angle from h to u, u_l / sqrt(u_h^2 + u_l^2 + v_e^2)
  // (|u| in the plane regularised: u's direction means nothing where |u| < v_e), all times D.
  const double floor_times_d = gains_.min_speed * c.denominator;
  const double turn =
      gains_.heading_gain * leftward_times_d /
      std::sqrt(forward_times_d * forward_times_d + leftward_times_d * leftward_times_d +
                floor_times_d * floor_times_d);
  DriveRates rates;
  switch (type_) {
    case RobotType::ThreeAxisRolling:  // the contact point moves with R theta' h - R phi' l (eq 33)
      rates.roll_rate = forward * inverse_radius_;
      rates.lateral_rate = -leftward * inverse_radius_;
      rates.turn_rate = turn;
      break;
    case RobotType::TwoAxisRolling:
      rates.roll_rate = forward * inverse_radius_;
      rates.lateral_rate = -leftward * inverse_radius_;
      break;
    case RobotType::RollingAndTurning:  // R theta' h only (eq 38): u's sideways part by turning
      rates.roll_rate = forward * inverse_radius_;
      rates.turn_rate = turn;
      break;
    case RobotType::RollingAndSteering: {
      // RS turns only while it rolls (eq 44), so it rolls forward at the cardioid speed
      // (|u| + u.h) / 2: u.h when heading along u, |u| / 2 with u abeam, 0 only with u straight
      // behind; at R alpha' cos(phi) (eq 48). The turn comes from the tilt: eq 44 inverted,
      // sin(phi*) = -turn / alpha', regularised where alpha' -> 0 and bounded smoothly by
      // max_tilt; the tilt rate servos phi towards phi*, smoothly bounded by max_tilt_rate.
      // |u| by sqrt, not hypot: speeds of metres per second neither overflow nor underflow.
      const double planar_speed = std::sqrt(forward * forward + leftward * leftward);
      rates.roll_rate = 0.5 * (planar_speed + forward) * inverse_radius_ / std::cos(tilt);
      const double roll_floor = gains_.min_speed * inverse_radius_;
      const double sine = -turn * rates.roll_rate /
                          (rates.roll_rate * rates.roll_rate + roll_floor * roll_floor);
      const double target_tilt =
          std::asin(max_tilt_sine_ * std::tanh(sine / max_tilt_sine_));
      rates.lateral_rate =
          gains_.max_tilt_rate *
          std::tanh(gains_.tilt_gain * (target_tilt - tilt) / gains_.max_tilt_rate);
      break;
    }
  }
  return rates;
}

}  // namespace spherical_robots::terrain
