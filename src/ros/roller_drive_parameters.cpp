#include "spherical_robots/ros/roller_drive_parameters.hpp"

#include <cmath>

#include "spherical_robots/config/roller_config.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {

const std::vector<std::string>& rollerMotorNames() {
  static const std::vector<std::string> names(config::kRollerActuatorNames.begin(),
                                              config::kRollerActuatorNames.end());
  return names;
}

roller::RollerActuation loadRollerActuation(const ros::NodeHandle& nh) {
  return config::makeRollerActuation(config::loadRollerConfig(RosParameterSource(nh)),
                                     radiusFromRobotDescription(nh));
}

void describeRollerDrive(const roller::RollerActuation& actuation,
                         diagnostic_updater::DiagnosticStatusWrapper& status) {
  const auto& rollers = actuation.drive().geometry().rollers();
  status.add("sphere radius [m]", actuation.drive().geometry().radius());
  status.add("roller radius [m]", actuation.rollerRadius());
  status.addf("alpha1, alpha2 [deg]", "%.6g, %.6g", rollers[0].alpha * 180.0 / M_PI,
              rollers[1].alpha * 180.0 / M_PI);
}

}  // namespace spherical_robots
