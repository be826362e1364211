#include "spherical_robots/terrain/teleop.hpp"
#include "spherical_robots/core/validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots::terrain {

TeleopMapping::TeleopMapping(RobotType type, double radius, double tilt_limit, double tilt_gain)
    : type_(type), radius_(radius), tilt_limit_(tilt_limit), tilt_gain_(tilt_gain) {
  requirePositive(radius, "teleop: radius [m]");
  requirePositive(tilt_gain, "teleop: tilt gain [1/s]");
  if (!(tilt_limit > 0.0 && tilt_limit < M_PI / 2.0)) {
    throw std::invalid_argument("teleop: tilt limit must be in (0, pi/2) rad, got " +
                                std::to_string(tilt_limit));
  }
}

TeleopCommand TeleopMapping::command(const VelocityRequest& request, double tilt) const {
  if (!std::isfinite(request.forward) || !std::isfinite(request.leftward) ||
      !std::isfinite(request.yaw_rate) || !std::isfinite(tilt)) {
    std::ostringstream problem;
    problem << "teleop: request (forward " << request.forward << " m/s, leftward "
            << request.leftward << " m/s, yaw " << request.yaw_rate << " rad/s) or tilt " << tilt
            << " rad is not finite";
    throw std::invalid_argument(problem.str());
  }
  const std::array<bool, 3> actuated = actuatedRates(type_);
  TeleopCommand result;
  result.rates.roll_rate = request.forward / radius_;
  if (type_ == RobotType::RollingAndSteering) {
    const double max_sin = std::sin(tilt_limit_);
    const double alpha_dot = result.rates.roll_rate;
    const double target_tilt =
        alpha_dot == 0.0 ? 0.0 : std::asin(std::clamp(-request.yaw_rate / alpha_dot, -max_sin, max_sin));
    result.rates.lateral_rate = tilt_gain_ * (target_tilt - tilt);
    if (request.leftward != 0.0) result.ignored.emplace_back("leftward");
    return result;
  }
  if (actuated[1]) {
    result.rates.lateral_rate = -request.leftward / radius_;
  } else if (request.leftward != 0.0) {
    result.ignored.emplace_back("leftward");
  }
  if (actuated[2]) {
    result.rates.turn_rate = request.yaw_rate;
  } else if (request.yaw_rate != 0.0) {
    result.ignored.emplace_back("yaw_rate");
  }
  return result;
}

}  // namespace spherical_robots::terrain
