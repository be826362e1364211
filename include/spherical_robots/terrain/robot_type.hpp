#pragma once
// The four kinematic classes of spherical robot (paper section 4) and their drive rates.

#include <array>
#include <string>
#include <vector>

#include "spherical_robots/core/enum_names.hpp"

namespace spherical_robots::terrain {

enum class RobotType {
  ThreeAxisRolling,    ///< 3R: rolls about l and h and turns about n (eqs 32-35)
  TwoAxisRolling,      ///< 2R: rolls about l and h, never turns (eqs 36-37)
  RollingAndTurning,   ///< RT: rolls about l and turns about n (eqs 38-39)
  RollingAndSteering,  ///< RS: rolls about its tilted axle, steers by tilting (eqs 40-50)
};

/// "3R", "2R", "RT", "RS" <-> RobotType. @throw std::invalid_argument on an unknown name.
inline constexpr EnumNames<RobotType, 4> kRobotTypeNames = {
    {{RobotType::ThreeAxisRolling, "3R"}, {RobotType::TwoAxisRolling, "2R"},
     {RobotType::RollingAndTurning, "RT"}, {RobotType::RollingAndSteering, "RS"}}};
inline RobotType robotTypeFromString(const std::string& name) {
  return enumFromName(kRobotTypeNames, name, "robot type");
}
inline std::string toString(RobotType type) { return enumName(kRobotTypeNames, type); }

/// Drive rates [rad/s]. roll_rate is theta_dot (about l) or, for RS, alpha_dot (about the tilted
/// axle); lateral_rate is phi_dot (about h: a sideways roll, or the RS tilt rate); turn_rate is
/// psi_dot (about n). For RS, turn_rate is not commanded: it follows from eq 44.
struct DriveRates {
  double roll_rate = 0.0;
  double lateral_rate = 0.0;
  double turn_rate = 0.0;
};

/// Which of (roll_rate, lateral_rate, turn_rate) the type actuates.
std::array<bool, 3> actuatedRates(RobotType type);

/// Names of the rates in DriveRates order, nullptr where the type does not actuate one:
/// 3R {"theta", "phi", "psi"}, 2R {"theta", "phi", -}, RT {"theta", -, "psi"}, RS {"alpha", "phi", -}.
/// These are the actuator (joint) names on actuators/command and actuators/state.
std::array<const char*, 3> rateNames(RobotType type);

/// The rates with every rate the type does not actuate set to 0 (RS turn_rate included).
DriveRates keepActuated(RobotType type, const DriveRates& rates);

/// The same with actuated = actuatedRates(type) looked up once (inline: the batch run's kinematics
/// apply it at every RK stage).
inline DriveRates keepActuated(const std::array<bool, 3>& actuated, const DriveRates& rates) {
  return {actuated[0] ? rates.roll_rate : 0.0, actuated[1] ? rates.lateral_rate : 0.0,
          actuated[2] ? rates.turn_rate : 0.0};
}

/// The names of the actuators the type has, in DriveRates order (the non-null rateNames()): the
/// names on actuators/command and actuators/state, e.g. RT {"theta", "psi"}.
std::vector<std::string> actuatorNames(RobotType type);

/// The actuated rates as a list in actuatorNames() order.
std::vector<double> actuatedValues(RobotType type, const DriveRates& rates);

/// DriveRates from values in actuatorNames() order, the rest 0.
/// @throw std::invalid_argument if there are not as many values as actuators.
DriveRates ratesFromActuated(RobotType type, const std::vector<double>& values);

}  // namespace spherical_robots::terrain
