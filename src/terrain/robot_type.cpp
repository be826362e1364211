#include "spherical_robots/terrain/robot_type.hpp"

#include <stdexcept>

namespace spherical_robots::terrain {

std::array<bool, 3> actuatedRates(RobotType type) {
  switch (type) {
    case RobotType::ThreeAxisRolling: return {true, true, true};
    case RobotType::TwoAxisRolling: return {true, true, false};
    case RobotType::RollingAndTurning: return {true, false, true};
    case RobotType::RollingAndSteering: return {true, true, false};
  }
  throw std::invalid_argument("invalid RobotType value");
}

std::array<const char*, 3> rateNames(RobotType type) {
  switch (type) {
    case RobotType::ThreeAxisRolling: return {"theta", "phi", "psi"};
    case RobotType::TwoAxisRolling: return {"theta", "phi", nullptr};
    case RobotType::RollingAndTurning: return {"theta", nullptr, "psi"};
    case RobotType::RollingAndSteering: return {"alpha", "phi", nullptr};
  }
  throw std::invalid_argument("invalid RobotType value");
}

DriveRates keepActuated(RobotType type, const DriveRates& rates) {
  return keepActuated(actuatedRates(type), rates);
}

namespace {

double& rateAt(DriveRates& rates, std::size_t i) {
  return *std::array<double*, 3>{&rates.roll_rate, &rates.lateral_rate, &rates.turn_rate}.at(i);
}

}  // namespace

std::vector<std::string> actuatorNames(RobotType type) {
  std::vector<std::string> names;
  for (const char* name : rateNames(type))
    if (name != nullptr) names.emplace_back(name);
  return names;
}

std::vector<double> actuatedValues(RobotType type, const DriveRates& rates) {
  const std::array<bool, 3> actuated = actuatedRates(type);
  const std::array<double, 3> all{rates.roll_rate, rates.lateral_rate, rates.turn_rate};
  std::vector<double> values;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (actuated[i]) values.push_back(all[i]);
  return values;
}

DriveRates ratesFromActuated(RobotType type, const std::vector<double>& values) {
  const std::array<bool, 3> actuated = actuatedRates(type);
  DriveRates rates;
  std::size_t k = 0;
  for (std::size_t i = 0; i < actuated.size(); ++i) {
    if (!actuated[i]) continue;
    if (k == values.size()) break;
    rateAt(rates, i) = values[k++];
  }
  if (k != values.size() || values.size() != actuatorNames(type).size())
    throw std::invalid_argument(std::to_string(values.size()) + " rates for the " +
                                std::to_string(actuatorNames(type).size()) + " actuators of a " +
                                toString(type) + " robot");
  return rates;
}

}  // namespace spherical_robots::terrain
