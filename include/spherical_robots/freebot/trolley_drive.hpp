#pragma once
// The FreeBOT driving trolley's differential wheels (Zong, Liang, Lam 2022, section IV-C3 and
// appendix C): wheel speeds ↔ trolley forward and steering speeds, eqs 64, 65. No ROS.
//
// The trolley runs on the inner surface (radius r_in) of the shell (outer radius r_out). Its
// wheels, l_w apart, touch the inner surface at r' = sqrt(r_in² − (l_w/2)²) from the axis the
// shell turns about (eq 83); the forward speed u_f is the speed of the shell's outer surface
// relative to the trolley, r_out times the shell's rate (eq 85). u_s is the trolley's yaw rate
// about the shell's normal at the trolley (eq 87).

namespace spherical_robots::freebot {

/// Trolley speeds: u_f [m/s] forward, u_s [rad/s] steering (counter-clockwise about the outward
/// normal of the tangent plane).
struct TrolleySpeeds {
  double forward = 0.0;
  double steering = 0.0;
};

/// Wheel rotation speeds [rad/s], positive driving the trolley forward.
struct WheelSpeeds {
  double right = 0.0;
  double left = 0.0;
};

class TrolleyDrive {
 public:
  /// Geometry [m] (Table II: 0.005, 0.046, 0.032, 0.034).
  /// @throw std::invalid_argument if a length is not finite and > 0, r_in > r_out, or
  /// l_w >= 2 r_in (the shell cannot hold the wheels).
  TrolleyDrive(double wheel_radius, double wheel_interval, double inner_radius,
               double outer_radius);

  double wheelRadius() const { return wheel_radius_; }
  double wheelInterval() const { return wheel_interval_; }
  double innerRadius() const { return inner_radius_; }
  double outerRadius() const { return outer_radius_; }
  /// r' of eq 83 [m].
  double wheelContactRadius() const { return contact_radius_; }

  /// Eq 64. @throw std::invalid_argument on a non-finite speed.
  TrolleySpeeds trolleySpeeds(const WheelSpeeds& wheels) const;
  /// Eq 65. @throw std::invalid_argument on a non-finite speed.
  WheelSpeeds wheelSpeeds(const TrolleySpeeds& trolley) const;

 private:
  double wheel_radius_;
  double wheel_interval_;
  double inner_radius_;
  double outer_radius_;
  double contact_radius_;
};

}  // namespace spherical_robots::freebot
