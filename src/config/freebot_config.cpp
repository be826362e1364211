#include "spherical_robots/config/freebot_config.hpp"

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace spherical_robots::config {
namespace {

const std::string kRoot = "freebot/";

/// Each named field read from prefix + name, > 0; an absent key keeps the value values holds.
template <typename Struct>
void readPositive(const ParameterSource& source, const std::string& prefix, Struct& values,
                  std::initializer_list<std::pair<const char*, double Struct::*>> fields) {
  for (const auto& [name, member] : fields)
    values.*member = positiveNumber(source, prefix + name, values.*member);
}

}  // namespace

freebot::FreebotChain freebotChain(const ParameterSource& source) {
  using G = freebot::TrolleyGeometry;
  const std::string radii_key = kRoot + "radii";
  const std::optional<std::vector<double>> radii = source.numbers(radii_key);
  if (!radii)
    throw std::invalid_argument(source.origin() + ": parameter '" + radii_key +
                                "' (list of sphere radii [m], base first) is required");
  freebot::TrolleyGeometry trolley;
  readPositive(source, kRoot + "trolley/", trolley,
               {{"wheel_radius", &G::wheel_radius}, {"wheel_interval", &G::wheel_interval},
                {"shell_thickness", &G::shell_thickness}});
  try {
    return freebot::FreebotChain(*radii, trolley);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source.origin() + ": parameters '" + radii_key + "', '" + kRoot +
                                "trolley': " + e.what());
  }
}

freebot::GoalExecutiveParameters freebotGoalExecutive(const ParameterSource& source) {
  using P = freebot::GoalExecutiveParameters;
  using D = freebot::DriveLimits;
  using K = freebot::TrolleyGains;
  using I = freebot::IkOptions;
  freebot::GoalExecutiveParameters p;
  readPositive(source, kRoot + "ik/", p.ik,
               {{"position_tolerance", &I::position_tolerance},
                {"orientation_tolerance", &I::orientation_tolerance}});
  p.ik.restarts = wholeNumber(source, kRoot + "ik/restarts", p.ik.restarts, 0);
  p.ik.max_iterations = wholeNumber(source, kRoot + "ik/max_iterations", p.ik.max_iterations, 1);
  readPositive(source, kRoot + "gains/", p.gains,
               {{"forward", &K::forward}, {"steering", &K::steering},
                {"alignment", &K::alignment}});
  readPositive(source, kRoot + "drive/", p.limits,
               {{"max_forward_speed", &D::max_forward_speed},
                {"max_steering_speed", &D::max_steering_speed},
                {"max_wheel_speed", &D::max_wheel_speed},
                {"heading_tolerance", &D::heading_tolerance},
                {"contact_tolerance", &D::contact_tolerance},
                {"steering_distance", &D::steering_distance}});
  readPositive(source, kRoot + "goal/", p,
               {{"position_tolerance", &P::position_tolerance},
                {"orientation_tolerance", &P::orientation_tolerance}, {"timeout", &P::timeout}});
  p.max_replans = wholeNumber(source, kRoot + "goal/max_replans", p.max_replans, 0);
  return p;
}

}  // namespace spherical_robots::config
