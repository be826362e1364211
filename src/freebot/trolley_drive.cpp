#include "spherical_robots/freebot/trolley_drive.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::freebot {

TrolleyDrive::TrolleyDrive(double wheel_radius, double wheel_interval, double inner_radius,
                           double outer_radius)
    : wheel_radius_(wheel_radius),
      wheel_interval_(wheel_interval),
      inner_radius_(inner_radius),
      outer_radius_(outer_radius) {
  requireLength(wheel_radius, "wheel radius r_w [m]");
  requireLength(wheel_interval, "wheel interval l_w [m]");
  requireLength(inner_radius, "shell inner radius r_in [m]");
  requireLength(outer_radius, "shell outer radius r_out [m]");
  std::ostringstream message;
  message.precision(17);
  if (inner_radius > outer_radius) {
    message << "shell inner radius r_in [m] must be <= outer radius r_out = " << outer_radius
            << ", got " << inner_radius;
    throw std::invalid_argument(message.str());
  }
  if (wheel_interval >= 2.0 * inner_radius) {
    message << "wheel interval l_w [m] must be < 2 r_in = " << 2.0 * inner_radius
            << " (the shell cannot hold the wheels), got " << wheel_interval;
    throw std::invalid_argument(message.str());
  }
  contact_radius_ = 0.5 * std::sqrt(4.0 * inner_radius * inner_radius -
                                    wheel_interval * wheel_interval);  // eq 83
}

TrolleySpeeds TrolleyDrive::trolleySpeeds(const WheelSpeeds& wheels) const {
  requireMagnitudeAtMost(wheels.right, kMaxSpeed, "right wheel speed w_r [rad/s]");
  requireMagnitudeAtMost(wheels.left, kMaxSpeed, "left wheel speed w_l [rad/s]");
  TrolleySpeeds trolley;
  // Eq 64; r_out r_w / sqrt(4 r_in² − l_w²) = r_out r_w / (2 r').
  trolley.forward =
      outer_radius_ * wheel_radius_ / (2.0 * contact_radius_) * (wheels.right + wheels.left);
  trolley.steering = wheel_radius_ / wheel_interval_ * (wheels.right - wheels.left);
  return trolley;
}

WheelSpeeds TrolleyDrive::wheelSpeeds(const TrolleySpeeds& trolley) const {
  requireMagnitudeAtMost(trolley.forward, kMaxSpeed, "trolley forward speed u_f [m/s]");
  requireMagnitudeAtMost(trolley.steering, kMaxSpeed, "trolley steering speed u_s [rad/s]");
  const double forward = contact_radius_ / (outer_radius_ * wheel_radius_) * trolley.forward;
  const double steering = wheel_interval_ / (2.0 * wheel_radius_) * trolley.steering;
  return {forward + steering, forward - steering};  // eq 65
}

}  // namespace spherical_robots::freebot
