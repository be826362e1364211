#include "spherical_robots/freebot/freebot_chain.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::freebot {
namespace {

constexpr double kMaxHeadingStep = 0.01;  // [rad] per sub-step of advance()

std::vector<TrolleyDrive> trolleysOf(const std::vector<double>& radii,
                                     const TrolleyGeometry& trolley) {
  requirePositive(trolley.shell_thickness, "shell thickness r_out - r_in [m]");
  std::vector<TrolleyDrive> trolleys;
  for (std::size_t i = 1; i < radii.size(); ++i) {
    if (trolley.shell_thickness >= radii[i]) {
      std::ostringstream message;
      message.precision(17);
      message << "shell thickness r_out - r_in [m] must be < the radius of link " << i << " ("
              << radii[i] << "), got " << trolley.shell_thickness;
      throw std::invalid_argument(message.str());
    }
    trolleys.emplace_back(trolley.wheel_radius, trolley.wheel_interval,
                          radii[i] - trolley.shell_thickness, radii[i]);
  }
  return trolleys;
}

void requireCount(std::size_t count, std::size_t expected, const char* what) {
  if (count != expected) {
    throw std::invalid_argument(std::string(what) + " count must equal the number of modules (" +
                                std::to_string(expected) + "), got " + std::to_string(count));
  }
}

/// Scales both speeds by one factor so that they and the wheels they need fit the limits.
TrolleySpeeds limited(const TrolleyDrive& trolley, TrolleySpeeds speeds, const DriveLimits& limits) {
  double scale = 1.0;
  if (std::abs(speeds.forward) > limits.max_forward_speed)
    scale = std::min(scale, limits.max_forward_speed / std::abs(speeds.forward));
  if (std::abs(speeds.steering) > limits.max_steering_speed)
    scale = std::min(scale, limits.max_steering_speed / std::abs(speeds.steering));
  const WheelSpeeds wheels = trolley.wheelSpeeds(speeds);  // linear in the speeds (eq 65)
  const double fastest = std::max(std::abs(wheels.right), std::abs(wheels.left));
  if (fastest * scale > limits.max_wheel_speed) scale = limits.max_wheel_speed / fastest;
  speeds.forward *= scale;
  speeds.steering *= scale;
  return speeds;
}

}  // namespace

FreebotChain::FreebotChain(const std::vector<double>& radii, const TrolleyGeometry& trolley)
    : manipulator_(radii), trolleys_(trolleysOf(radii, trolley)) {}

ChainState FreebotChain::alignedState() const {
  return ChainState{std::vector<SrcJointState>(moduleCount()),
                    std::vector<double>(moduleCount(), 0.0)};
}

void FreebotChain::requireValid(const ChainState& state) const {
  manipulator_.requireValid(state.joints);
  requireCount(state.headings.size(), moduleCount(), "heading");
  for (std::size_t i = 0; i < state.headings.size(); ++i)
    requireFinite(state.headings[i], "trolley heading phi_" + std::to_string(i + 1) + " [rad]");
}

ChainState FreebotChain::advance(const ChainState& state, const std::vector<WheelSpeeds>& wheels,
                                 double dt) const {
  requireValid(state);
  requireCount(wheels.size(), moduleCount(), "wheel pair");
  requireFinite(dt, "time step dt [s]");
  if (dt < 0.0) throw std::invalid_argument("time step dt [s] must be >= 0, got " + std::to_string(dt));
  ChainState next = state;
  for (std::size_t i = 0; i < moduleCount(); ++i) {
    const SrcJoint& joint = manipulator_.joint(i);
    const TrolleySpeeds speeds = trolleys_[i].trolleySpeeds(wheels[i]);  // eq 64
    const double turn = speeds.steering * dt;
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(turn) / kMaxHeadingStep)));
    const double h = dt / steps;
    double heading = state.headings[i];
    for (int k = 0; k < steps; ++k) {
      if (speeds.forward != 0.0) {
        const double middle = heading + 0.5 * speeds.steering * h;
        next.joints[i] = joint.roll(next.joints[i], jointVelocityOf(joint, speeds.forward, middle),
                                    h);  // eq 51
      }
      heading += speeds.steering * h;  // eq 49
    }
    next.headings[i] = wrapToPi(heading);
  }
  return next;
}

std::vector<ModuleDrive> FreebotChain::drive(const ChainState& state,
                                             const std::vector<SrcJointState>& targets,
                                             const TrolleyGains& gains,
                                             const DriveLimits& limits) const {
  requireValid(state);
  manipulator_.requireValid(targets);
  requirePositive(limits.max_forward_speed, "max forward speed [m/s]");
  requirePositive(limits.max_steering_speed, "max steering speed [rad/s]");
  requirePositive(limits.max_wheel_speed, "max wheel speed [rad/s]");
  requirePositive(limits.heading_tolerance, "heading tolerance [rad]");
  requirePositive(limits.contact_tolerance, "contact tolerance [m]");
  requirePositive(limits.steering_distance, "steering distance [m]");
  std::vector<ModuleDrive> drives(moduleCount());
  for (std::size_t i = 0; i < moduleCount(); ++i) {
    ModuleDrive& out = drives[i];
    const ArcPlan plan = planArc(manipulator_.joint(i), state.joints[i], targets[i]);  // eqs 53-55
    out.distance = plan.distance;
    double direction = plan.direction;
    double distance = plan.distance;
    if (std::abs(wrapToPi(direction - state.headings[i])) > 0.5 * M_PI) {
      direction = wrapToPi(direction + M_PI);  // the target is behind: reverse
      distance = -distance;
    }
    out.heading_error = wrapToPi(direction - state.headings[i]);
    if (plan.distance <= limits.contact_tolerance) {
      out.arrived = true;
      continue;
    }
    TrolleySpeeds speeds;
    const bool aligned = std::abs(out.heading_error) <= limits.heading_tolerance;
    // Steer first (eq 56); once aligned, keep steering except over the last steering_distance,
    // where the heading to the contact point swings with every micrometre of lateral offset.
    if (!aligned || plan.distance > limits.steering_distance)
      speeds.steering = steeringSpeed(direction, 0.0, state.headings[i], gains);
    // Eq 63 with the remaining arc as s^r − s, projected on the heading as eq 57.
    if (aligned) speeds.forward = forwardSpeed(distance, 0.0, 0.0, gains) * std::cos(out.heading_error);
    out.trolley = limited(trolleys_[i], speeds, limits);
    out.wheels = trolleys_[i].wheelSpeeds(out.trolley);  // eq 65
  }
  return drives;
}

}  // namespace spherical_robots::freebot
